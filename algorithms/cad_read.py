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
        doc = _readfile(path)
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


class _NotPlain(Exception):
    """The fast tag reader met something it leaves to ezdxf's own reader (comments, a bad number...)."""


def _readfile(path: str):
    """``ezdxf.readfile(path)``, with the same document, for an ASCII DXF in less time (issue 13): ezdxf
    reads a file line by line through two chained generators (``ascii_tags_loader``, ``tag_compiler``: a
    third of its reading time on a SIST floor); here the text is read at once, split into lines, and the
    same tags are compiled in one loop (``_compiled_tags``), then loaded by ezdxf (``Drawing.from_tags``,
    the rest of ``readfile``). Anything the fast loop does not handle exactly as ezdxf does (binary DXF,
    comments, an unreadable number or group code, a point without its y, no end-of-file marker) goes
    to ``ezdxf.readfile`` itself, so errors and repairs are ezdxf's own."""
    import ezdxf
    from ezdxf.document import Drawing
    from ezdxf.filemanagement import dxf_file_info
    from ezdxf.lldxf.validator import is_binary_dxf_file, is_dxf_file

    if is_binary_dxf_file(path) or not is_dxf_file(path):
        return ezdxf.readfile(path)
    info = dxf_file_info(path)
    with open(path, mode="rt", encoding=info.encoding, errors="surrogateescape") as fp:
        text = fp.read()
    try:
        tags = _compiled_tags(text.split("\n"))
    except Exception:  # _NotPlain, ValueError, ...: ezdxf's reader decides (and names the problem)
        tags = None
    del text
    if tags is None:
        return ezdxf.readfile(path)
    doc = Drawing.from_tags(iter(tags))
    doc.filename = path
    return doc


def _compiled_tags(lines: List[str]):
    """The tags ``tag_compiler(ascii_tags_loader(stream))`` yields for the lines of an ASCII DXF (the text
    split at its newlines, as ``readline`` does in text mode), up to and including (0, EOF). Raises
    ``_NotPlain`` (or ValueError) where the fast path would have to differ from ezdxf's generators."""
    from ezdxf.lldxf.types import BINARY_DATA, POINT_CODES, TYPE_TABLE, DXFBinaryTag, DXFTag, DXFVertex

    codes, values = lines[0::2], lines[1::2]
    if len(values) < len(codes):
        codes = codes[:len(values)]
    end = -1
    start = 0
    while True:  # the first (0, "EOF"): ezdxf ignores whatever follows it
        try:
            k = values.index("EOF", start)
        except ValueError:
            raise _NotPlain("no end-of-file marker") from None
        if int(codes[k]) == 0:
            end = k + 1
            break
        start = k + 1
    icodes = list(map(int, codes[:end]))  # ValueError: an invalid group code (ezdxf raises its own error)
    if 999 in icodes:
        raise _NotPlain("comments")  # ezdxf drops them before compiling: points may span one
    vals = values[:end]
    out = []
    app = out.append
    get = TYPE_TABLE.get
    points, binary = POINT_CODES, BINARY_DATA
    j = 0
    m = end
    while j < m:
        code = icodes[j]
        v = vals[j]
        j += 1
        if code in points:
            if j >= m or icodes[j] != code + 10:
                raise _NotPlain("a point without its y coordinate")
            if j + 1 < m and icodes[j + 1] == code + 20:
                app(DXFVertex(code, (float(v), float(vals[j]), float(vals[j + 1]))))
                j += 2
            else:
                app(DXFVertex(code, (float(v), float(vals[j]))))
                j += 1
        elif code in binary:
            app(DXFBinaryTag.from_string(code, v))
        elif code == 0:
            app(DXFTag(0, v.strip()))
        else:
            cast = get(code)
            app(DXFTag(code, v if cast is None or cast is str else cast(v)))
    return out


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

