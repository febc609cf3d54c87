"""Sheet 2's indicator diagrams (issue 34): each piston's p(s) read back from the DXF — the polylines
in its field, at the scales printed under its heading — is the file's table; the positions' ordinates
end on the stroke acting; the fields find room without crossing the others (sheet_check)."""

from __future__ import annotations

import copy
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from sheet_check import all_texts, problems
from test_sheets import TITLE
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.sheets.dynamics_sheet import sheet2

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def _data(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def _single_cylinder():
    """compressor.toml with its table load replaced by an indicator diagram (head 0.33 m up the
    cylinder: the piston's top dead centre is r + l = 0.30 m from O)."""
    d = _data("compressor")
    d.pop("load", None)
    d["load"] = [{"on": "B", "head": [0.0, 0.33], "area": 0.00785, "travel": [0.0, 0.1, 0.3, 0.6, 1.0],
                  "pressure": [[0.9, 0.3, 0.0, -0.02, -0.02], [0.9, 0.9, 0.5, 0.1, -0.02]]}]
    return d


CASES = {"v_compressor": lambda: _data("v_compressor"), "single": _single_cylinder}


def _sheet(d, lang="ru"):
    m = parse_mechanism(copy.deepcopy(d), "t.toml")
    s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
    return m, s2, sheet2(s2, lang, TITLE)


def _fields(doc):
    out = {}
    for e in doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            out[tags[0]] = (tuple(tags[1:5]), tuple(tags[5:7]))
    return out


def _inside(pts, box):
    return all(box[0] <= x <= box[2] and box[1] <= y <= box[3] for x, y in pts)


def _printed_scales(doc, box):
    """μ_s [m/mm] and μ_p [MPa/mm] as printed in the field (a decimal comma)."""
    texts = [t for t in all_texts(doc) if "μs" in t and "μp" in t]
    for t in texts:
        m = re.search(r"μs = ([\d,]+) \S+; μp = ([\d,]+)", t)
        if m:
            return tuple(float(g.replace(",", ".")) for g in m.groups())
    raise AssertionError(f"no scale line in {texts}")


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_drawn_diagram_is_the_files_table(case):
    d = CASES[case]()
    m, s2, sh = _sheet(d)
    assert not sh.unplaced, sh.unplaced
    pr = problems(sh.doc)
    assert not pr, pr[:8]
    fields = _fields(sh.doc)
    loads = d["load"]
    mu_s, mu_p = _printed_scales(sh.doc, None)
    # H independently: each cylinder's line passes through the crank's pivot, so the stroke is 2r
    H = 2.0 * d["crank"]["length"]
    for ld in loads:
        number = m.link(ld["on"]).number
        box, origin = fields[f"indicator_{number}"]
        polys = [np.array([(p[0], p[1]) for p in e.get_points("xy")]) for e in sh.doc.modelspace().query("LWPOLYLINE")
                 if e.dxf.layer == "Основные" and _inside(e.get_points("xy"), box)]
        travel = np.array(ld["travel"])
        drawn = [((p[:, 0] - origin[0]) * mu_s / H, (p[:, 1] - origin[1]) * mu_p) for p in polys if len(p) == len(travel)]
        for j, row in enumerate(ld["pressure"]):
            hit = [(x, p) for x, p in drawn if (np.allclose(x, travel, atol=1e-6) and np.allclose(p, row, atol=1e-6))
                   or (np.allclose(x[::-1], travel, atol=1e-6) and np.allclose(p[::-1], row, atol=1e-6))]
            assert hit, f"row {j + 1} of load on {ld['on']} is not drawn at μ_s = {mu_s}, μ_p = {mu_p}"
            x, _ = hit[0]
            away = j % 2 == 0  # the first stroke moves away from the head: s grows
            assert (x[-1] > x[0]) == away
        # the fields sit inside the frame and off the other fields
        for name, (other, _) in fields.items():
            if name == f"indicator_{number}":
                continue
            overlap = min(box[2], other[2]) - max(box[0], other[0]), min(box[3], other[3]) - max(box[1], other[1])
            assert min(overlap) <= 1e-6, f"indicator_{number} overlaps {name}"


def test_the_scales_and_marks_are_the_cores():
    d = _data("v_compressor")
    m, s2, sh = _sheet(d)
    assert [i.link for i in s2.indicators] == ["B", "C"]
    for ind in s2.indicators:
        # round μ (1, 2, 2,5, 4, 5 × 10^k), the stroke within 150 mm, the largest pressure within 40 mm
        for mu in (ind.mu_s, ind.mu_p):
            mant = mu / 10.0 ** np.floor(np.log10(mu))
            assert min(abs(mant - c) for c in (1.0, 2.0, 2.5, 4.0, 5.0, 10.0)) < 1e-9
        assert ind.stroke / ind.mu_s <= 150.0 + 1e-9
        assert max(abs(v) for r in ind.pressure for v in r) / ind.mu_p <= 40.0 + 1e-9
        assert ind.mu_F == pytest.approx(ind.mu_p * 1e6 * ind.area)
        # the marks: position 0 is the first piston's dead centre nearest its head (s/H 0, moving away)
        assert len(ind.marks) == len(s2.sheet1.cycle.positions)
    first = s2.indicators[0]
    assert first.marks[0][1:] == (0, pytest.approx(0.0, abs=1e-9))
    # the marks' s/H independently: the piston's distance from its head along the cylinder
    kin = s2.sheet1.cycle.kin
    for ind, ld in zip(s2.indicators, d["load"]):
        head = complex(*ld["head"])
        dist = np.abs(kin.z[ld["on"]] - head)
        near = abs(head) - (d["crank"]["length"] + d["group"][0]["length"])  # the head beyond the top dead centre
        got = np.array([mk[2] for mk in ind.marks])
        assert got == pytest.approx(np.clip((dist - near) / ind.stroke, 0, 1), abs=1e-9)


def test_english_and_no_gas_no_field():
    _, _, sh = _sheet(_data("v_compressor"), "en")
    assert any("INDICATOR DIAGRAM, PISTON 3" in t for t in all_texts(sh.doc))
    assert any("1 — away from the head" in t for t in all_texts(sh.doc))
    _, s2, sh = _sheet(_data("shaper"))
    assert s2.indicators == () and not any(k.startswith("indicator") for k in _fields(sh.doc))


def test_the_notes_figure():
    """Chapter 2's figure of the indicator diagrams: listed between the plans and the dynamics for a
    file with gas loads (and not without), at its printed size, its lines the file's table [mm, MPa]."""
    from types import SimpleNamespace

    from tmm_cli.render.figures.note import note_figure, note_style
    from tmm_cli.render.figures.note_scales import figure_size_cm
    from tmm_cli.render.note import note_figures

    d = _data("v_compressor")
    m, s2, _ = _sheet(d)
    r = SimpleNamespace(cam=None, gears=None, linkage=s2)
    names = note_figures(r)
    assert names.index("linkage_plans") < names.index("linkage_indicator") < names.index("linkage_dynamics")
    _, plain, _ = _sheet(_data("shaper"))
    assert "linkage_indicator" not in note_figures(SimpleNamespace(cam=None, gears=None, linkage=plain))
    with note_style():
        fig = note_figure(r, "ru", "linkage_indicator")
        w, h = fig.get_size_inches()
        assert (w * 2.54, h * 2.54) == pytest.approx(figure_size_cm("linkage_indicator", None, s2), abs=0.01)
        H = 2000.0 * d["crank"]["length"]  # [mm]
        for ax, ld in zip([a for a in fig.axes if a.get_ylabel().startswith("p")], d["load"]):
            lines = [(ln.get_xdata(), ln.get_ydata()) for ln in ax.get_lines() if len(ln.get_xdata()) == len(ld["travel"])]
            for row in ld["pressure"]:
                assert any(np.allclose(np.sort(x), np.array(ld["travel"]) * H) and
                           np.allclose(np.asarray(y)[np.argsort(x, kind="stable")], row) for x, y in lines)


def test_a_four_stroke_diagram_draws_its_four_strokes():
    """A two-turn cycle's diagram (4 rows: expansion, exhaust, intake, compression — what a
    four-stroke engine's file gives) is drawn stroke by stroke, each named under the field; the
    strokes away from the head run with s growing."""
    import dataclasses

    from tmm_cli.render.sheets import indicator_view
    from tmm_cli.render.sheets.paper import Sheet

    _, s2, _ = _sheet(_data("v_compressor"))
    travel = (0.0, 0.1, 0.3, 0.6, 1.0)
    rows = ((4.0, 2.5, 1.2, 0.6, 0.3), (0.3, 0.12, 0.1, 0.1, 0.1), (-0.02, -0.02, -0.02, -0.02, -0.02),
            (-0.02, 0.05, 0.2, 0.6, 1.8))
    ind = dataclasses.replace(s2.indicators[0], travel=travel, pressure=rows,
                              strokes=("expansion", "exhaust", "intake", "compression"), mu_p=0.1)
    sh = Sheet("ru")
    sh.frame()
    w, h = indicator_view.size(sh, ind, "ru")
    indicator_view.draw(sh, ind, "ru", (40.0, 40.0, 40.0 + w, 40.0 + h))
    sh.finish()
    assert not sh.unplaced, sh.unplaced
    texts = " | ".join(all_texts(sh.doc))
    for k, word in enumerate(("расширение", "выпуск", "впуск", "сжатие"), start=1):
        assert f"{k} — {word}" in texts
    origin = _fields(sh.doc)["indicator_3"][1]
    polys = [np.array(e.get_points("xy")) for e in sh.doc.modelspace().query("LWPOLYLINE")
             if e.dxf.layer == "Основные" and len(e) == len(travel)]
    for j, row in enumerate(rows):
        hit = [p for p in polys if np.allclose((p[:, 1] - origin[1]) * 0.1, row if j % 2 == 0 else row[::-1])]
        assert hit, j
        assert (hit[0][-1, 0] > hit[0][0, 0]) == (j % 2 == 0)
