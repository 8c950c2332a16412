"""Opening a CAD file: the single place a drawing is read (DXF through ezdxf, with recover mode and an
in-memory salvage of truncated or damaged files). Every repair is returned as a message."""
from __future__ import annotations

import os
from typing import List

from .errors import InputError


def check_drawing_file(path: str, kind: str, head_size: int, empty_advice: str):
    """The checks every drawing file gets before it is decoded: it exists, is a file and holds data (not only
    NUL bytes or white space). ``kind`` ("DXF", "DWG") names the file in the errors, ``empty_advice`` says
    what to do with an empty one. Returns (file name, size in bytes, its first ``head_size`` bytes)."""
    if not os.path.exists(path):
        raise InputError(f"{kind} file '{path}' does not exist")
    if os.path.isdir(path):
        raise InputError(f"'{path}' is a folder, not a {kind} file")
    base = os.path.basename(path)
    size = os.path.getsize(path)
    with open(path, "rb") as fh:
        head = fh.read(head_size)
    if size == 0 or not head.strip(b"\x00 \t\r\n"):
        raise InputError(f"'{base}' is empty ({size} bytes, no drawing data); {empty_advice}")
    return base, size, head


def _read_doc(path: str, progress):
    """Read a DXF; fall back to ezdxf's recover mode and report what it repaired."""
    import ezdxf
    from ezdxf import recover

    from . import cad_dwg  # DWG input: read straight into the same structures (no temporary DXF)

    if cad_dwg.is_dwg(path):
        return cad_dwg.read_dwg(path, progress)
    base, _, head = check_drawing_file(path, "DXF", 4096, "export the plan again as DXF")
    if head[:4] == b"AC10" or head[:6] == b"AC1.40":
        raise InputError(f"'{base}' is a DWG file, not a DXF; convert it to DXF first (e.g. with the ODA File "
                         "Converter, LibreCAD or 'Save As DXF' in your CAD program)")
    if head.startswith(b"AutoCAD Binary DXF"):
        pass  # ezdxf reads binary DXF
    elif b"SECTION" not in head.upper() and b"\n0\n" not in head.replace(b"\r\n", b"\n") \
            and not head.lstrip().startswith(b"0"):
        raise InputError(f"'{base}' is not a DXF file (no DXF group codes found at its start); choose a .dxf "
                         "drawing exported from your CAD program")
    repairs: List[str] = []
    try:
        doc = ezdxf.readfile(path)
        return doc, repairs
    except Exception as first:  # DXFStructureError, UnicodeDecodeError, ValueError...
        first_msg = f"{type(first).__name__}: {first}"
    doc = auditor = None
    rec_msg = ""
    try:
        doc, auditor = recover.readfile(path)
    except Exception as exc:
        rec_msg = f"{type(exc).__name__}: {exc}"
    truncated = _is_truncated(path)
    if doc is None or (truncated and len(doc.modelspace()) == 0):
        salvaged = _salvage(path)
        if salvaged is not None:
            stream, notes = salvaged
            try:
                doc, auditor = recover.read(stream)
                repairs.extend(notes)
            except Exception as exc:
                rec_msg = rec_msg or f"{type(exc).__name__}: {exc}"
    if doc is None:
        raise InputError(f"'{base}' is not a readable DXF file, even in ezdxf's recover mode ({first_msg}; "
                         f"recover: {rec_msg}). Open and re-save it in a CAD program, "
                         "or export it again as DXF")
    if truncated and not repairs:
        repairs.append("the file is truncated: it ends without the DXF end-of-file marker")
    repairs.append(f"the file is damaged ({first_msg}); it was read in ezdxf's recover mode")
    for fix in list(getattr(auditor, "fixes", []))[:20]:
        repairs.append(f"fixed: {getattr(fix, 'message', fix)}")
    for err in list(getattr(auditor, "errors", []))[:20]:
        repairs.append(f"unfixable: {getattr(err, 'message', err)}")
    n_fix, n_err = len(getattr(auditor, "fixes", [])), len(getattr(auditor, "errors", []))
    if n_fix > 20 or n_err > 20:
        repairs.append(f"({n_fix} fixes and {n_err} unfixable errors in total)")
    return doc, repairs


def _is_truncated(path: str) -> bool:
    try:
        with open(path, "rb") as fh:
            fh.seek(max(0, os.path.getsize(path) - 64))
            tail = fh.read()
    except OSError:
        return False
    return b"EOF" not in tail.upper()


_FLOAT_CODES = [(10, 59), (110, 149), (210, 239), (460, 469), (1010, 1059)]
_INT_CODES = [(60, 99), (170, 179), (270, 299), (370, 389), (400, 409), (420, 429), (440, 459), (1060, 1071)]


def _code_kind(code: int) -> str:
    if any(a <= code <= b for a, b in _FLOAT_CODES):
        return "f"
    if any(a <= code <= b for a, b in _INT_CODES):
        return "i"
    return "s"


def _salvage(path: str):
    """Rebuild a damaged ASCII DXF in memory for recover mode: drop every entity (or header variable)
    holding an unreadable number, stop at a broken group structure or at the end of a truncated file,
    and close the open section. Returns ``(stream, notes)`` or None."""
    import io

    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    if data.startswith(b"AutoCAD Binary DXF"):
        return None
    lines = data.replace(b"\r\n", b"\n").replace(b"\r", b"\n").split(b"\n")
    out: List[bytes] = []
    unit: List[bytes] = []
    unit_bad = False
    dropped, bad_lines = 0, []
    stopped_at = None
    i = 0
    n = len(lines) - 1
    while i < n:
        code_txt, value = lines[i].strip(), lines[i + 1]
        try:
            code = int(code_txt)
        except ValueError:
            stopped_at = i + 1
            break
        if code in (0, 9):  # a new entity / table entry / section marker or header variable
            if unit_bad:
                dropped += 1
            else:
                out.extend(unit)
            unit, unit_bad = [], False
        unit.extend((lines[i], value))
        kind = _code_kind(code)
        if kind != "s":
            try:
                float(value.strip()) if kind == "f" else int(value.strip())
            except ValueError:
                unit_bad = True
                bad_lines.append(i + 2)
        i += 2
    ended = bool(unit) and unit[0].strip() == b"0" and unit[1].strip() == b"EOF"
    if ended and not unit_bad:
        out.extend(unit)
    notes = []
    if dropped or (unit_bad and not ended):
        notes.append(f"dropped {dropped + (1 if unit_bad and not ended else 0)} entities with unreadable numbers "
                     f"(lines {', '.join(map(str, bad_lines[:10]))}{'…' if len(bad_lines) > 10 else ''})")
    if not ended:
        why = (f"its group structure breaks at line {stopped_at}" if stopped_at is not None
               else "it ends without the DXF end-of-file marker")
        notes.append(f"the file is truncated or broken ({why}); what precedes was read, the rest is missing")
        out.extend([b"  0", b"ENDSEC", b"  0", b"EOF"])
    if not notes:
        return None
    return io.BytesIO(b"\n".join(out) + b"\n"), notes


def _layer_states(doc):
    states = {}
    for lay in doc.layers:
        try:
            states[lay.dxf.name] = (bool(lay.is_frozen()), bool(lay.is_off()))
        except Exception:
            continue
    return states

