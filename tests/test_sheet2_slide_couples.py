"""The couples the slides pass on, drawn on sheet 2's group views (the note gives them: M₀₃ of the
Scotch yoke's guide, M₃₄ and M₀₅ of the tangent mechanism's blocks, M₃₅ of the rocking block's
slider on its moving guide). Read back from the DXF and checked against linkage.json (not against
the code that draws them): each non-zero couple of the force position is a curved arrow centred on
its block's joint, named M_ij as the note names it, turning as the sign of `couple_Nm` says
(counter-clockwise positive); the group that holds the block's guide gets it back as M_ji; a couple
that is zero is not drawn."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from sheet_check import text_boxes
from test_lever_labels import MECHANISMS, sheet2_dxf
from tmm_cli.cli import cli

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ["scotch_yoke", "tangent", "rocking_block", "shaper"]


def fields(doc) -> dict:
    """Each group field's box and transform (origin, paper mm per real mm) from its XDATA."""
    out = {}
    for e in doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            if tags[0].startswith("group_"):
                out[tags[0]] = (tuple(tags[1:5]), (tags[5], tags[6]), tags[7])
    return out


def xy(v) -> np.ndarray:
    return np.array([v[0], v[1]])


def arc_sense(doc, arc) -> int:
    """+1 when the arrowhead (a SOLID) at one end of the arc points counter-clockwise, −1 clockwise."""
    c, r = xy(arc.dxf.center), arc.dxf.radius
    for e in doc.modelspace().query("SOLID"):
        tip = xy(e.dxf.vtx0)
        base = (xy(e.dxf.vtx1) + xy(e.dxf.vtx2)) / 2
        if abs(np.hypot(*(base - c)) - r) > 0.6 or np.hypot(*(tip - c)) > r + 1.0:
            continue
        for a in (arc.dxf.start_angle, arc.dxf.end_angle):
            end = c + r * np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
            if np.hypot(*(base - end)) < 3.0:
                ccw = np.array([-(end - c)[1], (end - c)[0]])
                return 1 if float(np.dot(tip - base, ccw)) > 0 else -1
    raise AssertionError("no arrowhead at the arc's ends")


@pytest.fixture(scope="module", params=NAMES)
def drawn(request, tmp_path_factory):
    name = request.param
    folder = tmp_path_factory.mktemp(name)
    res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--no-plots", "--out", str(folder),
                                   "--lang", "ru"])
    assert res.exit_code == 0, res.output
    data = json.loads((folder / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    _, doc = sheet2_dxf(name, dict(MECHANISMS)[f"{name}.toml"], folder)
    return name, data, doc


def expected(data) -> list[tuple[str, str, float]]:
    """(label, joint, moment [N·m]) of every slide couple of the force position the sheet must draw:
    M_ij on the block (j) and M_ji back on the guide's link (i) unless that is the frame."""
    label = data["forces"]["position"]
    pos = next(p for p in data["positions"] if p["label"] == label)
    scale = max(max(math.hypot(*f["force"]) for f in p["applied_forces"].values()) for p in data["positions"])
    scale = max(scale * data["crank"]["length_m"],
                max((abs(m) for p in data["positions"] for m in p["applied_moments_Nm"].values()), default=0.0))
    group_of = {n: g["index"] for g in data["structure"]["groups"] for n in g["links"] if n != 0}
    out = []
    for part in pos["reaction_parts"].values():
        m = part.get("couple_Nm")
        i, j = part["links"]
        if m is None or abs(m) <= 1e-9 * scale or group_of.get(i) == group_of[j]:
            continue  # no couple, a zero one, or one inside a group (not a load on its view)
        out.append((f"M{i}{j}", part["joint"], m))
        if i != 0:
            out.append((f"M{j}{i}", part["joint"], -m))
    return out


def test_the_slide_couples_are_drawn_with_their_sense(drawn):
    name, data, doc = drawn
    want = expected(data)
    if name == "shaper":  # its slider's load and mass act at its pin: M05 = 0, nothing drawn
        assert want == []
    else:
        assert any(lab.startswith(("M03", "M34", "M35")) for lab, _, _ in want), want
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    flds = fields(doc)
    texts = text_boxes(doc)
    arcs = list(doc.modelspace().query("ARC"))
    for lab, joint, m in want:
        found = []
        for key, (box, origin, k) in flds.items():
            for _e, c, _h, _r, t in texts:
                mid = c.mean(axis=0)
                if t == lab and box[0] <= mid[0] <= box[2] and box[1] <= mid[1] <= box[3]:
                    found.append((key, origin, k, mid))
        assert len(found) == 1, f"{name}: {lab} is named once on a group view ({found})"
        key, origin, k, mid = found[0]
        pt = pos["points"][joint]
        at = np.array([origin[0] + k * pt["x"] * 1000.0, origin[1] + k * pt["y"] * 1000.0])
        mine = [a for a in arcs if np.hypot(*(xy(a.dxf.center) - at)) < 0.05]
        assert mine, f"{name}: no arc about {joint} on {key}"

        def arc_mid(a):
            t = math.radians((a.dxf.start_angle + (a.dxf.end_angle - a.dxf.start_angle) % 360.0 / 2))
            return xy(a.dxf.center) + a.dxf.radius * np.array([math.cos(t), math.sin(t)])

        arc = min(mine, key=lambda a: np.hypot(*(arc_mid(a) - mid)))
        assert np.hypot(*(arc_mid(arc) - mid)) < 12.0, f"{name}: {lab} stands away from its arc"
        assert arc_sense(doc, arc) == (1 if m > 0 else -1), f"{name}: {lab} = {m} N·m turns the wrong way"
    # no other slide couple is named on the sheet
    names = {lab for lab, _, _ in want}
    for _e, _c, _h, _r, t in texts:
        if t.startswith("M") and t[1:].isdigit():
            assert t in names, f"{name}: {t} drawn, but it is zero in linkage.json"
