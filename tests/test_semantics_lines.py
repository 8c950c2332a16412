"""Stage 5: the lines of one multi-line label joined in the texts' own frame, and stacked complete names
kept apart (algorithms/semantics.py: group_lines, _two_names)."""
import math

import pytest

from algorithms import semantics as S
from algorithms.model import CadText


def T(text, x, y, rot=0.0, h=0.3, layer="TXT"):
    return CadText(x=x, y=y, text=text, height=h, rotation=rot, layer=layer, entity="TEXT")


def turned(texts, deg, mirror=False):
    """The texts as a drawing turned by ``deg`` (counter-clockwise, after an optional x -> -x mirror) shows
    them: positions turned, rotation turned (a mirrored text's rotation becomes 180 - r, as the importer
    reads a mirrored INSERT)."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    out = []
    for t in texts:
        x, r = (-t.x, 180.0 - t.rotation) if mirror else (t.x, t.rotation)
        out.append(T(t.text, x * c - t.y * s, x * s + t.y * c, (r + deg) % 360.0, t.height, t.layer))
    return out


# a room name over two lines beside a second label, and a name over its number, in one drawing
PLAN = [T("Sala", 10.0, 10.0), T("riunioni", 9.9, 9.55),
        T("Ufficio", 20.0, 10.0), T("direttore", 19.8, 9.55),
        T("Archivio", 30.0, 10.0), T("101", 30.2, 9.55)]


def names(texts):
    """The room names (and shaft labels, which the rules class as ignored) read from the texts."""
    return sorted(lab.text for lab in S.classify_labels(texts) if lab.role != "number")


@pytest.mark.parametrize("deg,mirror", [(0.0, False), (17.0, False), (30.0, False), (89.0, False), (90.0, False),
                                        (300.0, False), (333.0, False), (0.0, True), (30.0, True), (90.0, True),
                                        (315.0, True)])
def test_two_line_names_read_as_one_on_a_turned_or_mirrored_drawing(deg, mirror):
    assert names(turned(PLAN, deg, mirror)) == ["Archivio", "Sala riunioni", "Ufficio direttore"]
    labs = {lab.text: lab for lab in S.classify_labels(turned(PLAN, deg, mirror))}
    assert labs["101"].role == "number"  # a number stays a line of its own


@pytest.mark.parametrize("deg", [135.0, 180.0, 250.0])
def test_upside_down_lines_join_in_reverse_order(deg):
    # the rotation alone cannot tell an upside-down text from a mirrored one (read as mirrored): the lines
    # of a plan turned upside down still join, their order reversed (a known limit)
    assert names(turned(PLAN, deg)) == ["Archivio", "direttore Ufficio", "riunioni Sala"]


def test_turned_lines_join_only_along_their_own_frame():
    # turned 30 deg: the second line is 0.45 m below in the text frame; in page axes it is also 0.23 m to
    # the side, which the upright join did not accept
    texts = turned(PLAN[:2], 30.0)
    S.TEXT_FRAME_JOIN = False
    try:
        assert names(texts) == ["Sala", "riunioni"]  # the old join: only upright texts
    finally:
        S.TEXT_FRAME_JOIN = True
    assert names(texts) == ["Sala riunioni"]
    # side by side in the text frame (one line's height apart along the line, not below): never joined
    side = turned([T("Sala", 10.0, 10.0), T("riunioni", 13.0, 10.0)], 30.0)
    assert names(side) == ["Sala", "riunioni"]
    # lines of different rotations are not one label
    mixed = [T("Sala", 10.0, 10.0, rot=30.0), T("riunioni", 10.2, 9.6, rot=60.0)]
    assert names(mixed) == ["Sala", "riunioni"]


@pytest.mark.parametrize("deg", [0.0, 30.0, 90.0])
@pytest.mark.parametrize("upper,lower", [("排风井", "清洁间"), ("Bagno", "Ripostiglio"), ("WC", "Stair"),
                                         ("Kitchen", "Kitchen"), ("水井", "理论与计算研究室"), ("送风", "女卫生间"),
                                         ("男卫生间", "水")])
def test_two_stacked_complete_names_stay_two(deg, upper, lower):
    # two neighbouring small rooms (shafts, closets) named one line apart: each line a name of its own kind
    # ('理论与计算研究室' ends in the generic '室': a complete name), or a note ('送风' supply air) over a name
    texts = turned([T(upper, 10.0, 10.0), T(lower, 10.0, 9.6)], deg)
    assert names(texts) == sorted([upper, lower])
    S.STACKED_NAMES_GUARD = False
    try:
        assert names(texts) == [f"{upper} {lower}"]  # without the guard: one wrong name
    finally:
        S.STACKED_NAMES_GUARD = True


@pytest.mark.parametrize("upper,lower", [("Sala", "riunioni"), ("WC", "uomini"), ("Ufficio", "direttore"),
                                         ("Technical", "room"), ("Vano", "scala"), ("Magazzino", "deposito")])
def test_one_name_over_two_lines_is_not_split_by_the_guard(upper, lower):
    # a keyword across the lines ('sala riunioni', 'vano scala'), one kind on both lines, or a line without
    # a room word: one name
    assert not S._two_names(upper, lower, S._resolve(None))
    assert names([T(upper, 10.0, 10.0), T(lower, 10.0, 9.6)]) == [f"{upper} {lower}"]


def test_a_note_keeps_its_second_line():
    # a note's second line without a room word is part of the note, not a room name
    labs = {lab.text: lab for lab in S.classify_labels(turned([T("PISO DE LADRILLO", 20.0, 5.2, h=0.12),
                                                                 T("ESPINA DE PEZ", 20.1, 5.0, h=0.12)], 30.0))}
    assert list(labs) == ["PISO DE LADRILLO ESPINA DE PEZ"] and labs["PISO DE LADRILLO ESPINA DE PEZ"].role == "ignored"
