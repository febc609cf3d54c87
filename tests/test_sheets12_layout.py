"""Sheets 1 and 2 (the lever mechanism) as a normcontroller reads them (issue 21: «Sheet 1 and 2
follow the same rules»), for every mechanism of docs/examples and the Whitworth mechanism of the
options form (`tmm linkage --r1 … --b …`) at several sets of options, other positions of the plans
and other numbers of positions: every entity inside the frame and one field, no text crossed by a
line or over text, text heights, readable directions, dashed polylines flagged (and drawn as dashes
by ezdxf's drawing add-on), the views at the core's scales, and every number printed agreeing
with linkage.json to its last printed digit.

The checks read the DXF document back (tests/sheet_check.py), not the code that placed things.
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from sheet_check import all_texts, field_boxes, mtext_runs, problems
from test_sheets import TITLE
from tmm_cli.linkage.analysis import analyse
from tmm_cli.linkage.geometry import make_geometry
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.linkage.vector_plans import book_symbol
from tmm_cli.render.data.dynamics import add_sheet2
from tmm_cli.render.data.mechanism import mechanism_document
from tmm_cli.render.sheets.dynamics_sheet import sheet2
from tmm_cli.render.sheets.linkage_sheet import sheet1

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def _mechanism_files() -> list[str]:
    out = []
    for path in sorted(EXAMPLES.glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        if "crank" in data and "frame" in data:
            out.append(path.stem)
    return out


NAMES = _mechanism_files()
_CACHE: dict = {}


def analysed(name: str, plan=None, positions=None):
    """(Sheet1, Sheet2 or None) of an example as `tmm linkage` makes them (sheet 2 when the file
    gives masses or a load)."""
    key = (name, plan, positions)
    if key not in _CACHE:
        path = EXAMPLES / f"{name}.toml"
        m = parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name)
        if positions is not None:
            m = dataclasses.replace(m, positions=positions)
        s1 = analyse_mechanism(m, plan, path.name)
        inp = parse_sheet2(m, path.name)
        _CACHE[key] = (s1, analyse_sheet2(s1, inp, path.name) if inp.has_forces else None)
    return _CACHE[key]


# the Whitworth mechanism of the options form (tmm linkage --r1 --h --c --r2 --r3 --b --rpm), written
# as docs/examples/whitworth.toml writes it: O41 is h below and c left of O21, the crank turns
# clockwise, B on the slotted link r2 from O41, the ram C on the line y = b left of B
OPTIONS = [
    (0.10, 0.04, 0.0, 0.08, 0.30, -0.04, 60.0),  # the article's (seed 003) = docs/examples/whitworth.toml
    (0.16, 0.07, 0.03, 0.14, 0.55, 0.06, 90.0),
    (0.12, 0.05, -0.02, 0.10, 0.40, -0.08, 45.0),
    (0.10, 0.30, 0.0, 0.50, 0.20, 0.22, 60.0),  # the crank-shaper regime: the slotted link swings
]


def options_mechanism(r1, h, c, r2, r3, b, rpm, forces: bool):
    data = {
        "name": "Механизм Витворта", "positions": 12,
        "frame": {"O21": [0.0, 0.0], "O41": [-c, -h]},
        "crank": {"pivot": "O21", "joint": "A", "length": r1, "rpm": rpm, "sense": "cw"},
        "group": [{"kind": "RPR", "joints": ["A", "O41"]},
                  {"kind": "RRP", "joints": ["B", "C"], "length": r3,
                   "guide": {"through": [0.0, b], "angle_deg": 0.0}, "branch": "behind"}],
        "point": [{"name": "B", "link": ["O41", "A"], "along": r2}],
    }
    if forces:  # sheet 2's tables, so that the options' mechanism gets a sheet 2 too
        data["point"].append({"name": "S3", "link": ["O41", "A"], "along": r2 / 2})
        data["gravity"] = True
        data["mass"] = [{"link": ["O21", "A"], "m": 3.0, "J": 0.01, "centre": "O21"}, {"joint": "A", "m": 1.0, "J": 0.0},
                        {"link": ["O41", "A"], "m": 8.0, "J": 0.1, "centre": "S3"},
                        {"link": ["B", "C"], "m": 4.0, "J": 0.03}, {"joint": "C", "m": 20.0, "J": 0.0}]
        data["load"] = {"on": "C", "stroke": [0.0, 0.1, 0.1, 0.9, 0.9, 1.0], "force": [0, 0, 800, 800, 0, 0],
                        "working": "towards"}
        data["dynamics"] = {"delta": 0.04, "J_rotor": 1.0}
    return parse_mechanism(data, "options")


def _clean(sh):
    pr = problems(sh.doc)
    assert not pr, pr[:12]
    assert not sh.unplaced, sh.unplaced
    assert not sh.doc.audit().has_errors


# ----------------------------------------------------------------------------------------------
# norm-control


def test_the_examples_are_found():
    assert {"compressor", "four_bar", "shaper", "whitworth"} <= set(NAMES)


@pytest.mark.parametrize("name", NAMES)
def test_sheet1_passes_norm_control(name):
    s1, _ = analysed(name)
    _clean(sheet1(s1, "ru", TITLE))


@pytest.mark.parametrize("name", [n for n in NAMES if analysed(n)[1] is not None])
def test_sheet2_passes_norm_control(name):
    _, s2 = analysed(name)
    _clean(sheet2(s2, "ru", TITLE))


@pytest.mark.parametrize("opts", OPTIONS)
def test_whitworth_options_form(opts):
    m = options_mechanism(*opts, forces=True)
    s1 = analyse_mechanism(m)
    # the mechanism drawn is the options form's: the same stroke and time ratio
    ref = analyse(make_geometry(*opts[:6]), opts[6] * math.pi / 30.0)
    assert s1.cycle.stroke == pytest.approx(ref.stroke, rel=1e-9)
    assert s1.cycle.time_ratio == pytest.approx(ref.time_ratio, rel=1e-9)
    _clean(sheet1(s1, "ru", TITLE))
    _clean(sheet2(analyse_sheet2(s1, parse_sheet2(m)), "ru", TITLE))


def test_whitworth_options_form_is_the_example():
    s_opt = analyse_mechanism(options_mechanism(*OPTIONS[0], forces=False))
    s_ex, _ = analysed("whitworth")
    for n in ("A", "B", "C"):
        np.testing.assert_allclose(s_opt.cycle.kin.z[n], s_ex.cycle.kin.z[n], atol=1e-12)


@pytest.mark.parametrize("name,plan,positions", [("shaper", "0", None), ("shaper", "7′", None), ("four_bar", "6′", None),
                                                 ("compressor", "5", 24), ("four_bar", None, 36), ("shaper", None, 8),
                                                 ("whitworth", None, 72)])
def test_other_plans_and_positions(name, plan, positions):
    s1, s2 = analysed(name, plan, positions)
    _clean(sheet1(s1, "ru", TITLE))
    if s2 is not None:
        _clean(sheet2(s2, "ru", TITLE))


@pytest.mark.parametrize("name", ["shaper", "four_bar"])
def test_english(name):
    s1, s2 = analysed(name)
    for sh in (sheet1(s1, "en", TITLE), sheet2(s2, "en", TITLE)):
        _clean(sh)
        # outside the title block (ГОСТ 2.104's captions, the names) no Russian is left
        outside = [t for t, x, y in _placed_texts(sh.doc) if not (x > 651 and y < 60)]
        assert not [t for t in outside if re.search("[А-Яа-яЁё]", t)], outside
    assert "SCHEME OF THE MECHANISM IN ITS POSITIONS" in " ".join(_texts(sheet1(s1, "en", TITLE).doc))


# ----------------------------------------------------------------------------------------------
# the core's scales and numbers


_texts = all_texts


def _placed_texts(doc) -> list[tuple[str, float, float]]:
    out = [(e.dxf.text, e.dxf.insert[0], e.dxf.insert[1]) for e in doc.modelspace().query("TEXT")]
    out += [("".join(t for t, _ in mtext_runs(e.text)[0]), e.dxf.insert[0], e.dxf.insert[1])
            for e in doc.modelspace().query("MTEXT")]
    return out


def _fields(doc) -> dict:
    out = {}
    for e in doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            out[tags[0]] = {"box": tuple(tags[1:5]), "origin": tuple(tags[5:7]), "scale": tags[7], "label": tags[8]}
    return out


@pytest.mark.parametrize("name", NAMES)
def test_views_at_the_cores_scales(name):
    s1, s2 = analysed(name)
    fl = _fields(sheet1(s1, "ru", TITLE).doc)
    assert fl["scheme"]["scale"] == pytest.approx(1.0 / (s1.scheme_scale * 1000.0))
    for pl in s1.plans:
        lab = pl.position.label.replace("′", "'")
        assert fl[f"velocity_plan_{lab}"]["scale"] == pytest.approx(1.0 / pl.velocity.scale)
        assert fl[f"acceleration_plan_{lab}"]["scale"] == pytest.approx(1.0 / pl.acceleration.scale)
    if s2 is not None:
        fl = _fields(sheet2(s2, "ru", TITLE).doc)
        for pg in s2.polygons:
            assert fl[f"polygon_{pg.group}"]["scale"] == pytest.approx(1.0 / pg.scale)
        groups = {f["label"] for k, f in fl.items() if k.startswith("group_")}
        assert len(groups) == 1 and groups <= {"1:1", "1:2", "1:2,5", "1:4", "1:5", "1:10", "2:1", "2,5:1", "4:1", "5:1"}


_NUM = re.compile(r"(-?\d+(?:[ \u202f]\d{3})*(?:,\d+)?)")


def _values(texts: list[str]) -> dict[str, list[str]]:
    """Every `symbol = number` printed (symbols as plain text, 'vBA', 'RnB12'), the numbers as printed."""
    out: dict[str, list[str]] = {}
    for t in texts:
        for part in re.split(r";\s+", t):
            part = re.sub(r"^[^=:;]*:\s+", "", part)  # a caption's heading («найдены: R… = …»)
            m = re.match(r"\s*([^\s=]+(?: [^\s=]+)?)\s*=\s*" + _NUM.pattern, part)
            if m:
                out.setdefault(m.group(1).strip(), []).append(m.group(2))
    return out


def _agrees(printed: str, value: float) -> bool:
    """The printed number is `value` rounded to the digits printed."""
    s = printed.replace(" ", "").replace("\u202f", "").replace(",", ".")
    dec = len(s.split(".")[1]) if "." in s else 0
    return abs(float(s) - value) <= 0.5 * 10.0 ** -dec * (1 + 1e-9) + 1e-12


@pytest.mark.parametrize("name", NAMES)
def test_sheet1_numbers_agree_with_linkage_json(name):
    s1, _ = analysed(name)
    doc = mechanism_document(s1, "ru")
    vals = _values(_texts(sheet1(s1, "ru", TITLE).doc))
    checked = 0
    for k, pl in enumerate(doc["plans"]):
        for kind in ("velocity", "acceleration"):
            plan = pl[kind]
            seen = set()
            for v in plan["vectors"]:
                # as the sheet writes it: a sliding point with its link's number (v_BB3 → v_B5B3;
                # tests/test_relative_symbols.py checks that form independently)
                sym = book_symbol(s1.mechanism, v["symbol"]).replace("^", "").replace("_", "")
                if sym in seen:
                    continue
                seen.add(sym)
                assert sym in vals, (sym, sorted(vals))
                assert any(_agrees(p, v["magnitude"]) for p in vals[sym]), (sym, vals[sym], v["magnitude"])
                checked += 1
            # the plan's scale
            mu = "μv" if kind == "velocity" else "μa"
            assert any(_agrees(p, plan["scale"]) for p in vals[mu]), (mu, vals[mu], plan["scale"])
        # ω and ε of the links at the plan's position
        entry = next(e for e in doc["positions"] if e["label"] == pl["position"])
        for ln in s1.mechanism.links:
            if ln.kind not in ("bar", "slotted"):
                continue
            for key, sym in (("omega", f"ω{ln.number}"), ("epsilon", f"ε{ln.number}")):
                assert any(_agrees(p, abs(entry["links"][ln.name][key])) for p in vals[sym]), (sym, vals[sym])
                checked += 1
    for key, sym in (("s", "μS" if s1.mechanism.output.kind == "slider" else "μψ"),
                     ("v", "μV" if s1.mechanism.output.kind == "slider" else "μω"),
                     ("a", "μa" if s1.mechanism.output.kind == "slider" else "με")):
        assert any(_agrees(p, doc["diagram_scales"][key]) for p in vals[sym]), (sym, vals[sym])
    assert any(_agrees(p, math.degrees(doc["diagram_scales"]["phi_rad_per_mm"])) for p in vals["μφ"])
    texts = " | ".join(_texts(sheet1(s1, "ru", TITLE).doc))
    if doc["stroke_m"] is not None:
        assert f"{doc['stroke_m'] * 1000:.2f}".replace(".", ",") + " мм" in texts
    if doc["time_ratio"] is not None:
        assert f"{doc['time_ratio']:.4f}".replace(".", ",") in texts
    worst = max(p["max_deg"] for p in doc["pressure_angles"])
    assert f"{worst:.1f}".replace(".", ",") + "°" in texts
    assert checked >= 8


@pytest.mark.parametrize("name", [n for n in NAMES if analysed(n)[1] is not None])
def test_sheet2_numbers_agree_with_linkage_json(name):
    s1, s2 = analysed(name)
    doc = add_sheet2(mechanism_document(s1, "ru"), s2)
    texts = _texts(sheet2(s2, "ru", TITLE).doc)
    vals = _values(texts)
    checked = 0
    for pg in doc["forces"]["polygons"]:
        for v in pg["vectors"]:
            sym = re.sub(r"^(R)(τ|n)", r"R\2", v["symbol"]).replace("Fc", "Fпс")
            if v["kind"] != "unknown" and v["length_mm"] >= 9.0:
                continue  # named on the polygon, its value in no caption
            assert sym in vals, (sym, sorted(vals))
            assert any(_agrees(p, v["magnitude"]) for p in vals[sym]), (sym, vals[sym], v["magnitude"])
            checked += 1
        assert any(_agrees(p, pg["scale_N_per_mm"]) for p in vals["μF"])
    pos = next(e for e in doc["positions"] if e["label"] == doc["forces"]["position"])
    joined = " | ".join(texts)
    dyn = doc["dynamics"]
    for value, decimals in ((pos["balancing_moment_Nm"], 2), (pos["zhukovsky_moment_Nm"], 2),
                            (pos["zhukovsky_moment_Nm"], 3), (pos["balancing_moment_Nm"], 3)):
        assert f"{value:.{decimals}f}".replace(".", ",") in joined, value
    assert f"{dyn['motor_moment_Nm']:.2f}".replace(".", ",") in joined
    if dyn["flywheel_inertia_kgm2"] is not None:
        for key in ("flywheel_inertia_kgm2", "flywheel_inertia_wittenbauer_kgm2"):
            sig = f"{dyn[key]:.4g}".replace(".", ",")
            assert sig in joined, (key, sig)
        assert any(_agrees(p, dyn["wittenbauer"]["tan_psi_max"]) for p in vals["tg ψmax"])
        assert any(_agrees(p, dyn["wittenbauer"]["tan_psi_min"]) for p in vals["tg ψmin"])
    assert checked >= 3


# ----------------------------------------------------------------------------------------------
# paper and dashes


def test_sheets_fill_their_frame_and_keep_the_title_block_free():
    s1, s2 = analysed("shaper")
    for sh in (sheet1(s1, "ru", TITLE), sheet2(s2, "ru", TITLE)):
        boxes = field_boxes(sh.doc)
        area = sum((b[2] - b[0]) * (b[3] - b[1]) for b in boxes.values())
        assert area > 0.8 * (816 - 4) * (584 - 4) - 185 * 55  # the fields cover the sheet
        for b in boxes.values():
            assert not (b[2] > 651 and b[1] < 60), b  # nothing under the title block


def test_dashes_render_in_ezdxfs_drawing_addon():
    """The paths of the centres of mass, the other extreme position and the guides' axes come out
    of ezdxf's drawing add-on (the PDF's renderer) as dashes."""
    from ezdxf.addons.drawing.recorder import Recorder

    from tmm_cli.render.sheets.pdf import draw

    s1, s2 = analysed("shaper")
    for doc in (sheet1(s1, "ru", TITLE).doc, sheet2(s2, "ru", TITLE).doc):
        drawn: dict = {}

        class Rec(Recorder):
            def store(self, record, properties, drawn=drawn):
                if properties.layer in ("Осевые", "Штриховые") and hasattr(record, "lines"):
                    ln = np.asarray(record.lines.vertices() if hasattr(record.lines, "vertices") else record.lines)
                    ln = ln.reshape(-1, 2, 2) if ln.ndim == 2 else ln
                    acc = drawn.setdefault(properties.layer, [0, 0.0])
                    acc[0] += len(ln)
                    acc[1] += float(np.hypot(*(ln[:, 1] - ln[:, 0]).T).sum())
                super().store(record, properties)

        draw(doc, Rec())
        total: dict = {}
        for e in doc.modelspace().query("LWPOLYLINE LINE"):
            if e.dxf.layer not in ("Осевые", "Штриховые"):
                continue
            if e.dxftype() == "LWPOLYLINE":
                p = np.array([q[:2] for q in e.get_points()])
                assert e.dxf.flags & 128
                if e.closed:
                    p = np.vstack([p, p[:1]])
                length = float(np.hypot(*np.diff(p, axis=0).T).sum())
            else:
                length = math.dist(e.dxf.start, e.dxf.end)
            total[e.dxf.layer] = total.get(e.dxf.layer, 0.0) + length
        assert "Штриховые" in drawn
        for layer, (pieces, length) in drawn.items():
            assert pieces > 4, layer
            assert 0.3 * total[layer] < length < 0.95 * total[layer], (layer, length, total[layer])
