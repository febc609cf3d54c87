"""Issue 34 review: the pair of forces that replaces a turning slider's couple on Zhukovsky's lever
stands at B and at a point Q the note defines (what it is, its distance along the guide, the pair's
force M/l with the substitution); sheet 2's lever draws q with its ray from p; the hatching of a
fixed guide (the shaper's ram guide) is on the side away from the rod B–C, in every position."""

from __future__ import annotations

import math
import re
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_sheets import TITLE  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
_CACHE: dict = {}


def data(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def sheet2(name):
    if name not in _CACHE:
        m = parse_mechanism(data(name), f"{name}.toml")
        _CACHE[name] = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m, f"{name}.toml"))
    return _CACHE[name]


def _number(text: str) -> float:
    return float(text.replace("\u202f", "").replace(" ", "").replace(",", ".").replace("−", "-"))


# --- the note ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["rocking_block", "shaper"])
def test_every_point_of_the_levers_table_is_a_joint_or_defined_before_it(name):
    from tmm_cli.project import analyse_linkage, run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.model import Formula, Paragraph, Table
    from tmm_cli.variants import get_variant

    s2 = analyse_linkage(data(name), f"{name}.toml")
    doc = build_note(run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml"), "ru", {})
    k = next(k for k, b in enumerate(doc.blocks) if isinstance(b, Table) and b.name == "dyn_lever")
    table = doc.blocks[k]
    points = {r[1] for r in table.rows if r[1]}
    # the mechanism's own points as the note writes them: B, O_2, S_3
    kin = s2.sheet1.cycle.kin
    own = {"$" + (re.sub(r"^([A-Z])(\d+)$", r"\1_\2", n)) + "$" for n in kin.z}
    strange = points - own
    before = [b for b in doc.blocks[:k] if isinstance(b, (Paragraph, Formula))]
    text = " ".join(getattr(b, "text", "") for b in before)
    if name == "shaper":
        assert not strange  # every force stands at a joint or a centre of mass
        return
    assert strange == {"$Q$"}  # the couple's second point: not a joint's letter (review C12: B′ named the PRP block)
    # defined: what it is, and its distance from B along the guide
    m = re.search(r'точке \$Q\$ — точке звена 5 \(на линии его направляющей\) на расстоянии '
                  r'\$l = "?([\d,]+)"?\$ м от \$B\$ вдоль направляющей', text)
    assert m, text[-900:]
    l_note = _number(m.group(1))
    # independently, from the lever's own images: |q − b| = |ω5|·l (Q is a point of the slider)
    s = sheet2(name)
    i = s.force_position
    at = {f.point: complex(f.lever[i]) for f in s.lever.forces}
    w5 = float(s.sheet1.cycle.kin.omega["B"][i])
    assert abs(at["Q"] - at["B"]) / abs(w5) == pytest.approx(l_note, rel=1e-3)
    # the pair's force M/l, with the substitution, right after the definition
    pair = next(b for b in before if isinstance(b, Formula) and "M_(Φ 5)/l" in b.math)
    nums = [_number(x) for x in re.findall(r'"([\d,\u202f]+)"', pair.math)]
    m5 = next(c for c in s.loading.couples if c.symbol == "MΦ5")
    assert nums[0] == pytest.approx(abs(float(m5.m[i])), rel=1e-4)
    assert nums[1] == pytest.approx(l_note)
    f5 = next(f for f in s.lever.forces if f.symbol == "MΦ5″")
    assert nums[2] == pytest.approx(abs(complex(f5.force[i])), rel=1e-3)
    assert nums[2] == pytest.approx(nums[0] / nums[1], rel=1e-3)


# --- sheet 2: q on the lever --------------------------------------------------------------------------


def test_the_levers_points_include_q_with_its_ray(tmp_path):
    import ezdxf

    from tmm_cli.render.sheets.dynamics_sheet import _lever_points, sheet2 as build

    s = sheet2("rocking_block")
    i = s.force_position
    kin = s.sheet1.cycle.kin
    plan = s.sheet1.plans[0].velocity
    pts = _lever_points(s)
    assert "q" in pts and "b" in pts
    # q is the turned velocity of Q = B + l·e (e along the slider's guide): v_B + i·ω·l·e
    from tmm_cli.linkage.zhukovsky import pair_arm

    l = pair_arm(s.sheet1.mechanism)
    v = complex(kin.v["B"][i]) + 1j * float(kin.omega["B"][i]) * l * complex(np.exp(1j * kin.angle["B"][i]))
    assert pts["q"] == pytest.approx(1j * v / plan.scale, rel=1e-9)
    sh = build(s, "ru", TITLE)
    sh.doc.saveas(tmp_path / "s2.dxf")
    doc = ezdxf.readfile(tmp_path / "s2.dxf")
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    mtexts = [e.text for e in doc.modelspace().query("MTEXT")]
    assert "q" in texts
    # the ray p q (main line) with the same ratio to p b as on the plan
    lines = [(np.array([e.dxf.start[0], e.dxf.start[1]]), np.array([e.dxf.end[0], e.dxf.end[1]])) for e in doc.modelspace().query("LINE[layer=='Основные']")]
    ratio = abs(pts["q"]) / abs(pts["b"])
    angle = math.degrees(math.atan2(pts["q"].imag, pts["q"].real))
    found = False
    for a, b in lines:
        d = b - a
        if abs(math.degrees(math.atan2(d[1], d[0])) - angle) < 0.05:
            for c, e in lines:
                if np.allclose(c, a, atol=1e-6) and abs(np.hypot(*(e - c)) * ratio - np.hypot(*d)) < 0.05:
                    found = True
    assert found
    # the pair's two arrows, at b and at q, labelled M′Φ5 and M″Φ5
    assert {"M\\S^ Φ5;'", "M\\S^ Φ5;''"} <= set(mtexts)


# --- sheet 1: the guide's hatching away from the rod --------------------------------------------------


def _segments(doc, layers=("Основные", "Тонкие")):
    out = []
    for e in doc.modelspace():
        if e.dxf.layer not in layers:
            continue
        if e.dxftype() == "LINE":
            out.append((e.dxf.layer, [(e.dxf.start[0], e.dxf.start[1]), (e.dxf.end[0], e.dxf.end[1])]))
        elif e.dxftype() == "LWPOLYLINE":
            p = [tuple(q[:2]) for q in e.get_points()]
            out.append((e.dxf.layer, p + p[:1] if e.closed else p))
    return out


def _cross(p, q, r, s):
    p, q, r, s = (np.asarray(x, float) for x in (p, q, r, s))
    d1, d2, w = q - p, s - r, r - p
    den = d1[0] * d2[1] - d1[1] * d2[0]
    if abs(den) < 1e-12:
        return False
    t = (w[0] * d2[1] - w[1] * d2[0]) / den
    u = (w[0] * d1[1] - w[1] * d1[0]) / den
    return 1e-6 < t < 1 - 1e-6 and 1e-6 < u < 1 - 1e-6


def _examples() -> list[str]:
    return [p.stem for p in sorted(EXAMPLES.glob("*.toml")) if "crank" in data(p.stem) and "frame" in data(p.stem)]


def _turns_fully(m, kin, pivot: str) -> bool:
    """Does a link pivoted at `pivot` turn through the whole circle over the cycle?"""
    links = [ln.name for ln in m.links if ln.axis and pivot in ln.axis] + [m.link_between(m.crank.pivot, m.crank.joint).name
                                                                            if pivot == m.crank.pivot else None]
    return any(np.ptp(np.unwrap(np.asarray(kin.angle[x], float))) > 2 * math.pi - 0.1 for x in links if x in kin.angle)


@pytest.mark.parametrize("name", _examples())
def test_the_frames_hatching_crosses_no_line_of_sheet_1(name):
    """No hatch stroke of a fixed guide or of a fixed pivot crosses any line of sheet 1 (the links of
    every drawn position — main, thin, dashed —, the paths, the other symbols), read from the DXF;
    every fixed guide keeps a hatched piece of 4 strokes at least, every fixed pivot 3 (the crank's 1)."""
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    m = parse_mechanism(data(name), f"{name}.toml")
    sh = sheet1(analyse_mechanism(m, None, f"{name}.toml"), "ru", TITLE)
    guide, pivot = math.hypot(1.8, 1.4), math.hypot(1.5, 1.8)  # hatching.STROKE, the pivot's strokes

    def kind(lay, p):
        if lay != "Тонкие" or len(p) != 2:
            return None
        d = math.dist(*p)
        return "guide" if abs(d - guide) < 0.02 else "pivot" if abs(d - pivot) < 0.02 else None

    segs = _segments(sh.doc, ("Основные", "Тонкие", "Штриховые"))
    hatch = [(kind(lay, p), p) for lay, p in segs if kind(lay, p)]
    fixed = sum(1 for _, g in m.guided() if not g.moving)
    assert sum(k == "guide" for k, _ in hatch) >= 4 * fixed
    # each fixed pivot keeps its strokes near it: 3 of 5 at least; the pivot of a link that turns
    # fully (the crank; Whitworth's slotted link), amid that link's positions, at least one
    kin = analyse_mechanism(m, None, f"{name}.toml").cycle.curve.kin
    head = next(e for e in sh.doc.modelspace() if e.has_xdata("TMM_FIELD")
                and e.get_xdata("TMM_FIELD")[0].value == "scheme")
    tags = [t.value for t in head.get_xdata("TMM_FIELD")]
    origin, scale = np.array(tags[5:7]), tags[7]
    for n, z in m.frame.items():
        if not any(n in ln.pins or (ln.axis and n in ln.axis) for ln in m.links):
            continue
        q = origin + scale * 1000.0 * np.array([z.real, z.imag])
        near = [p for k, p in hatch if k == "pivot" and math.dist(p[0], q) < 9.0]
        assert len(near) >= (1 if _turns_fully(m, kin, n) else 3), (n, len(near))
    crossings = [(k, h, a, b) for k, h in hatch for lay, o in segs if not kind(lay, o)
                 for a, b in zip(o[:-1], o[1:]) if _cross(h[0], h[1], a, b)]
    assert not crossings, crossings[:3]
    if name not in ("shaper", "shaper_offset"):
        return
    # and independently of the drawing: the rod's far end B is on one side of the guide in every
    # position (so a side free of it exists) — the hatching is on the other
    e = dict(m.guided())["C"].unit
    side = ((kin.z["B"] - kin.z["C"]) * np.conj(e)).imag
    assert np.all(side > 0) or np.all(side < 0)
