"""Zhukovsky's lever on sheet 2 as a reader sees it (issue 32: «Φ5, Φ4, M″Φ4, e, d pile up»):
measured on the DXF of every docs/examples mechanism with sheet 2 and of the teacher's six-link
(RRR + RRP on a vertical guide, the crank turning clockwise), the lever's names and its caption
overlap no other text and are crossed by no line — as osifont sets them and with the room a CAD
program's wider fallback font takes (1.3×)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import ezdxf
import numpy as np
import pytest

from sheet_check import _boxes_overlap, _seg_box_hits, entity_points, field_boxes, text_boxes
from test_sheets import TITLE
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.sheets.dynamics_sheet import sheet2 as build_sheet2

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"

SIX_LINK = """
name = "Шестизвенный механизм"
positions = 12
gravity = true
[frame]
O = [0.0, 0.0]
C = [0.30, 0.05]
[crank]
pivot = "O"
joint = "A"
length = 0.08
rpm = 60
sense = "cw"
[[group]]
kind = "RRR"
joints = ["A", "B", "C"]
lengths = [0.28, 0.20]
branch = "left"
[[point]]
name = "D"
link = ["C", "B"]
along = 0.10
across = 0.06
[[group]]
kind = "RRP"
joints = ["D", "E"]
length = 0.30
guide = { through = [0.45, 0.0], angle_deg = 90.0 }
branch = "ahead"
[[point]]
name = "S2"
link = ["A", "B"]
along = 0.14
[[point]]
name = "S4"
link = ["D", "E"]
along = 0.15
[[mass]]
link = ["O", "A"]
m = 0.8
J = 0.0006
centre = "O"
[[mass]]
link = ["A", "B"]
m = 2.2
J = 0.0145
centre = "S2"
[[mass]]
link = ["C", "B"]
m = 1.6
J = 0.0054
centre = "C"
[[mass]]
link = ["D", "E"]
m = 2.0
J = 0.01
centre = "S4"
[[mass]]
joint = "E"
m = 3.0
J = 0.0
[load]
on = "E"
stroke = [0.0, 0.5, 1.0]
force = [0.0, 800.0, 800.0]
working = "away"
"""


def _mechanisms() -> list[tuple[str, str]]:
    out = []
    for p in sorted(EXAMPLES.glob("*.toml")):
        text = p.read_text(encoding="utf-8")
        if "[crank]" in text:  # a mechanism file (the others are variant tables, chains, answers)
            out.append((p.name, text))
    return out + [("six_link (inline)", SIX_LINK)]


MECHANISMS = _mechanisms()


def sheet2_dxf(name: str, text: str, tmp_path):
    """(Sheet2, the DXF document read back) of a mechanism file's text; every label placed."""
    m = parse_mechanism(tomllib.loads(text), name)
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name))
    path = tmp_path / "sheet2.dxf"
    sh = build_sheet2(s, "ru", TITLE)
    assert not sh.unplaced, sh.unplaced
    sh.doc.saveas(path)
    return s, ezdxf.readfile(path)


def field_texts(doc, box, room: float):
    """(corners, text) of the names in a field `box` (its heading, 7 mm, left out) with the widths
    `room` times osifont's, and the field's lines as segments (p0, p1)."""
    def inside(pts, tol=0.5):
        return (pts[:, 0].min() >= box[0] - tol and pts[:, 0].max() <= box[2] + tol
                and pts[:, 1].min() >= box[1] - tol and pts[:, 1].max() <= box[3] + tol)

    segs = []
    for e in doc.modelspace():
        if e.dxftype() in ("TEXT", "MTEXT"):
            continue
        pts = entity_points(e)
        if pts is not None and len(pts) > 1 and inside(pts):
            segs += list(zip(pts[:-1], pts[1:]))
    p0, p1 = np.array([a for a, _ in segs]).reshape(-1, 2), np.array([b for _, b in segs]).reshape(-1, 2)
    texts = [(c, t) for _e, c, h, _r, t in text_boxes(doc, room) if inside(c, 0.0) and h < 6.9]
    return texts, (p0, p1)


def clashes(texts, segs) -> list[str]:
    """Each name crossed by a line of its field, and each pair of names that overlap."""
    p0, p1 = segs
    out = []
    for i, (ci, ti) in enumerate(texts):
        if len(p0) and _seg_box_hits(p0, p1, ci).any():
            out.append(f"{ti!r} is crossed by a line")
        for cj, tj in texts[i + 1:]:
            if _boxes_overlap(ci, cj):
                out.append(f"{ti!r} and {tj!r} overlap")
    return out


@pytest.mark.parametrize("name,text", MECHANISMS, ids=[n for n, _ in MECHANISMS])
def test_the_levers_labels_are_free(name, text, tmp_path):
    s, doc = sheet2_dxf(name, text, tmp_path)
    box = field_boxes(doc)["lever"]
    # drawn at the μ of the lever's table (the note's): the field's scale is 1/μ [mm per m/s]
    tags = next([t.value for t in e.get_xdata("TMM_FIELD")] for e in doc.modelspace()
                if e.has_xdata("TMM_FIELD") and e.get_xdata("TMM_FIELD")[0].value == "lever")
    assert 1.0 / tags[7] == pytest.approx(s.lever_scale(), rel=1e-9)
    for room in (1.0, 1.3):
        texts, segs = field_texts(doc, box, room)
        assert len(segs[0]) > 5  # the lever is drawn
        assert len(texts) >= 4
        names = {t for _, t in texts}
        assert "p" in " ".join(names)
        assert any(t.startswith(("F", "G", "Φ")) for t in names) or not s.lever.forces  # the forces are named
        assert not clashes(texts, segs), f"{name} (room {room}): {clashes(texts, segs)}"


@pytest.mark.parametrize("name,text", MECHANISMS, ids=[n for n, _ in MECHANISMS])
def test_the_lever_figures_names_do_not_overlap(name, text):
    """linkage_lever.png: the names of the points and forces, as matplotlib sets them, overlap no
    other name."""
    from tmm_cli.render.figures.dynamics import lever_figure

    m = parse_mechanism(tomllib.loads(text), name)
    s = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name))
    fig = lever_figure(s, "ru")
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    ax = fig.axes[0]
    boxes = [(t.get_text(), t.get_window_extent(r)) for t in ax.texts if t.get_text()]
    assert len(boxes) >= 4
    for i, (ti, bi) in enumerate(boxes):
        for tj, bj in boxes[i + 1:]:
            w = min(bi.x1, bj.x1) - max(bi.x0, bj.x0)
            h = min(bi.y1, bj.y1) - max(bi.y0, bj.y0)
            assert w <= 0.5 or h <= 0.5, f"{name}: {ti!r} and {tj!r} overlap in the figure"
