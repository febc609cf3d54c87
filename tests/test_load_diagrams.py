"""Each table load's own diagram on sheet 2 (review 2, finding 5: «диаграмма сил полезного
сопротивления» — the load against φ over the cycle, one row per load in the diagrams field, its
working strokes dimensioned).

Independent check, read back from the DXF (not from the code that drew it): in the diagrams field,
a polyline over one of the φ axes whose ordinates at every position equal the load recomputed from
the file's own table (its own link's extremes found on a fine grid, its share of the stroke from the
link's place: tests/test_linkage_several_loads.Own) at the μ printed in the field's caption, the
position's x at the printed μ_φ. For the press with a feeder (two loads: F_пс3 on the ram, M_пс5 on
the rocker) and the shaper (one load, with jumps in its table)."""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from sheet_check import all_texts, field_boxes
from test_linkage_several_loads import Own
from test_sheets import TITLE
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.render.sheets.dynamics_sheet import sheet2

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def _printed(texts, name: str) -> float:
    """The μ printed as «μ<name> = value unit» (index written inline) in the sheet's texts."""
    for t in texts:
        m = re.search(re.escape("μ" + name) + r" = ([\d,]+(?:·10\^?-?\d+)?)", t)
        if m:
            return float(m.group(1).replace(",", "."))
    raise AssertionError(f"μ{name} not printed: {[t for t in texts if 'μ' in t]}")


def _in(box, pts) -> bool:
    return bool(np.all((pts[:, 0] >= box[0] - 1e-6) & (pts[:, 0] <= box[2] + 1e-6) & (pts[:, 1] >= box[1] - 1e-6)
                       & (pts[:, 1] <= box[3] + 1e-6)))


def _rows(doc):
    """(the φ axes as (x0, y0), the curves as vertex arrays) of the diagrams field."""
    box = field_boxes(doc)["dynamics_diagrams"]
    msp = doc.modelspace()
    axes = []
    for e in msp.query("LINE"):
        a, b = e.dxf.start, e.dxf.end
        if abs(a[1] - b[1]) < 1e-9 and b[0] - a[0] > 150.0 and _in(box, np.array([[a.x, a.y], [b.x, b.y]])):
            axes.append((float(a[0]), float(a[1])))
    curves = [np.array([p[:2] for p in e.get_points()]) for e in msp.query("LWPOLYLINE")
              if len(e) > 50 and e.dxf.layer == "Основные"]
    return axes, [c for c in curves if _in(box, c)]


def _check(name: str, symbols: list[str]):
    path = EXAMPLES / f"{name}.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    loads = data["load"] if isinstance(data["load"], list) else [data["load"]]
    m = parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)
    s1 = analyse_mechanism(m)
    s2 = analyse_sheet2(s1, parse_sheet2(m, path.name), path.name)
    doc = sheet2(s2, "ru", TITLE).doc
    texts = all_texts(doc)
    mu_phi = _printed(texts, "φ")  # [°/mm]
    axes, curves = _rows(doc)
    positions = s1.cycle.positions
    for ld, sym in zip(loads, symbols):
        own = Own(m, {**data, "load": loads}, ld)
        mu = _printed(texts, sym)
        want = np.abs(np.array([complex(np.atleast_1d(own.value(p.phi)[0])[0]) for p in positions])) / mu  # [mm]
        assert np.max(want) > 5.0  # a diagram, not a line on the axis
        travel = np.array([math.degrees(p.travel) for p in positions]) / mu_phi  # [mm from the axis' start]
        found = []
        for x0, y0 in axes:
            for c in curves:
                if abs(c[0, 0] - x0) > 1e-6 or c[-1, 0] < x0 + travel.max() - 1e-6:
                    continue
                got = np.interp(x0 + travel, c[:, 0], c[:, 1]) - y0
                if np.max(np.abs(got - want)) < 0.05:  # to a twentieth of a millimetre at every position
                    found.append((x0, y0))
        assert found, (sym, want)
        label = "F" if "force" in ld else "M"
        assert any(t.startswith(label + sym[1:]) for t in texts), sym  # the axis named as the note names it
        assert any(t in ("рабочий ход", "рабочее качание") for t in texts)  # its working stroke dimensioned


def test_press_feeder_draws_both_loads_against_the_turn():
    _check("press_feeder", ["Fпс3", "Mпс5"])


def test_the_shaper_draws_its_single_load():
    _check("shaper", ["Fпс"])
