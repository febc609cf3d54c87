"""Sheet 2's group views draw their own links wholly and a neighbour only as a thin stub (review
finding B7, the tangent mechanism): group 1's slotted link 3 runs up to B, where the block B′ of group 2
presses on it (R43), instead of ending at A with R43 floating beside nothing; group 2's view does not
draw link 3 (not one of its links) full length as a solid line — only a thin dash-dot stub of its slot
under the block, as the book draws a neighbouring link."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
SHEET2 = [f.stem for f in sorted(EXAMPLES.glob("*.toml"))
          if "dynamics" in (d := tomllib.loads(f.read_text(encoding="utf-8"))) and "crank" in d]


def _s2(name):
    m = parse_mechanism(tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8")), name)
    return analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, name))


def _dist(q, p0, p1):
    d = p1 - p0
    t = min(1.0, max(0.0, ((q - p0) * d.conjugate()).real / (abs(d) ** 2 or 1.0)))
    return abs(q - (p0 + t * d))


@pytest.mark.parametrize("name", SHEET2)
def test_every_force_of_a_group_acts_on_a_drawn_link(name):
    """Each force on a group's links (applied, inertia, reactions) is applied at a point of the view's
    drawing of those links (a line, a plate's outline, a block, or a named point of the link drawn as a
    dot: an offset slot's centre of mass): none stands off in the air."""
    from tmm_cli.render.sheets.dynamics_sheet import _forces_on, _group_names, _group_segments

    s2 = _s2(name)
    i = s2.force_position
    unit = 2.0  # real mm per paper mm (any: the stubs and boxes scale with it)
    for g in range(len(s2.sheet1.mechanism.groups) + 1):
        segs = _group_segments(s2, g, i, unit)
        lines = [(sg[1], sg[2]) for sg in segs if sg[0] == "line"]
        lines += [(a, b) for sg in segs if sg[0] == "poly" for a, b in zip(sg[1][:-1], sg[1][1:])]
        boxes = [(sg[1], max(sg[3], sg[4]) * unit) for sg in segs if sg[0] == "box"]
        boxes += [(complex(s2.sheet1.cycle.kin.z[n][i]) * 1000, 0.0) for n in _group_names(s2, g)]
        for z, f, label, kind in _forces_on(s2, g, i, "en"):
            near = min([_dist(z, a, b) for a, b in lines] + [abs(z - c) - r for c, r in boxes] + [math.inf])
            assert near < 0.5, (name, g, label, kind, near)


def test_the_tangent_mechanisms_link_3_in_the_dxf():
    """Read back from sheet 2's DXF: one solid line along link 3 (group 1's view) at least as long as O2B
    at the view's scale; group 2's view has no solid line along it, only a thin dash-dot stub."""
    from tmm_cli.render.sheets.dynamics_sheet import sheet2

    s2 = _s2("tangent")
    i = s2.force_position
    kin = s2.sheet1.cycle.kin
    o2, b = complex(kin.z["O2"][i]), complex(kin.z["B"][i])
    along = math.atan2((b - o2).imag, (b - o2).real)
    doc = sheet2(s2, "ru", TitleFields()).doc
    k = None
    for e in doc.modelspace().query("TEXT MTEXT"):
        text = e.dxf.text if e.dxftype() == "TEXT" else e.text
        if text.startswith("М 1:"):
            k = 1.0 / float(text.split(";")[0][4:].replace(",", "."))
            break
    k = k or 0.5  # the groups' views are at M 1:2
    solid, centre = [], []
    for e in doc.modelspace().query("LWPOLYLINE"):
        pts = [complex(x, y) for x, y, *_ in e.get_points()]
        for p0, p1 in zip(pts[:-1], pts[1:]):
            d = p1 - p0
            if abs(d) < 1e-6:
                continue
            off = abs(math.remainder(math.atan2(d.imag, d.real) - along, math.pi))
            if off < math.radians(0.5):
                (solid if e.dxf.layer == "Основные" else centre if e.dxf.layer == "Осевые" else []).append(abs(d))
    full = abs(b - o2) * 1000 * k
    long_solid = [x for x in solid if x > 0.5 * full]
    assert len(long_solid) == 1 and long_solid[0] >= full - 0.5, (full, long_solid)
    assert any(15.0 < x < 25.0 for x in centre), centre  # the stub: 10 mm either side of the block B′
    assert np.isfinite(full)
