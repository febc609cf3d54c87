"""Issue 24: the note's chapter 1 (the lever mechanism of sheet 1) for the four example mechanisms.

The note is built (Markdown, no figures) for variant 17 with each example file; then
- the chapter is there, first, and every "formula = substitution = result" line reproduces;
- its numbers agree with linkage.json's, recomputed here from the file and the JSON (v_A = ω1·l_OA
  from the file's crank, W from counting the file's links and pairs, the stroke and K from the
  extreme positions in `positions`, the table of positions and the links' ω, ε of the plans'
  position from `positions`);
- the decisions it states (claims) hold; the Russian chapter speaks Russian;
- without a mechanism the note has no such chapter and keeps its old front matter.
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest

from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.data.mechanism import mechanism_document
from tmm_cli.render.note import build_note
from tmm_cli.render.note.markdown import markdown
from tmm_cli.render.note.mathsyntax import check_line, number_value, parse, to_text
from tmm_cli.render.note.model import Formula, Heading, Table, all_math
from tmm_cli.render.note.omml import omath_para
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ["shaper", "four_bar", "compressor", "whitworth"]
_CACHE: dict = {}


def tables(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def project(name):
    """ProjectResult of variant 17 with the mechanism: as `tmm project --mechanism` runs it where
    the file allows (a [load], a crank slow enough for a motor), else sheet 1-2 put beside it."""
    if name not in _CACHE:
        if name in ("shaper", "four_bar"):
            s2 = analyse_linkage(tables(name), f"{name}.toml")
            r = run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml")
        else:
            m = parse_mechanism(tables(name), name)
            s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
            r = replace(run_project(get_variant("17")), linkage=s2)
        _CACHE[name] = r
    return _CACHE[name]


def note(name, lang="ru"):
    key = (name, lang)
    if key not in _CACHE:
        _CACHE[key] = build_note(project(name), lang, {})
    return _CACHE[key]


def chapter_blocks(doc):
    """The blocks of chapter 1 (from its heading to the next chapter)."""
    out, inside = [], False
    for b in doc.blocks:
        if isinstance(b, Heading) and b.level == 1:
            if inside:
                break
            inside = b.label == "linkage"
        if inside:
            out.append(b)
    return out


def value(text: str) -> float:
    v = number_value(text.replace("\u00a0", "").strip())
    assert v is not None, text
    return v[0]


def result(doc, lhs: str) -> float:
    """The printed result of the formula line that starts with `lhs` (typst math)."""
    for b in chapter_blocks(doc):
        if isinstance(b, Formula):
            for piece in re.split(r"; quad | \\\\ ", b.math):
                if piece.startswith(lhs + " "):
                    tail = piece.rsplit(" = ", 1)[1]
                    num = re.match(r'"?([^"]+)"?', tail.split(" thin ")[0].strip())[1]
                    return value(num)
    raise AssertionError(f"no formula {lhs}")


def table(doc, name) -> Table:
    return next(b for b in doc.blocks if isinstance(b, Table) and b.name == name)


# ---------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_the_chapter_is_first_and_every_substitution_reproduces(name):
    doc = note(name)
    assert doc.off == []
    chapters = [b for b in doc.blocks if isinstance(b, Heading) and b.level == 1 and b.kind == "chapter"]
    labels = [c.label for c in chapters]
    # sheet 1's chapter first, then sheet 2's where the file has its tables, then the cam
    assert labels[0] == "linkage" and labels[1:3] in (["dynamics", "cam"], ["cam", "gears"]), labels
    checked = 0
    for b in chapter_blocks(doc):
        if isinstance(b, Formula):
            parse(b.math)
            assert len(omath_para(b.math)) >= 2  # a Word equation too
            for c in check_line(b.math):
                checked += 1
                assert c.ok, f"{c.text} {c.relation} {c.target} in: {b.math}"
    assert checked >= 12
    for kind, src in all_math(doc):
        parse(src)


@pytest.mark.parametrize("name", NAMES)
def test_the_numbers_agree_with_linkage_json(name):
    doc = note(name)
    r = project(name)
    s1 = r.linkage.sheet1
    data = mechanism_document(s1, "ru")
    raw = tables(name)
    # Chebyshev: the file's links and pairs counted here (crank + 2 per group; 1 + 3 per group pairs)
    groups = raw["group"]
    n, p5 = 1 + 2 * len(groups), 1 + 3 * len(groups)
    assert result(doc, "W") == 3 * n - 2 * p5 == 1
    # the crank: ω1 and v_A = ω1·l_OA from the file
    crank = raw["crank"]
    omega = crank["rpm"] * math.pi / 30 if "rpm" in crank else crank["omega"]
    assert result(doc, "ω_1") == pytest.approx(omega, rel=6e-4)
    joint = crank["joint"]
    assert result(doc, f"v_{joint}") == pytest.approx(omega * crank["length"], rel=6e-4)
    pos = data["positions"]
    by_label = {p["label"]: p for p in pos}
    first, last = (by_label[lab] for lab in data["extreme_positions"])
    out = data["output"]
    if out["kind"] == "slider":
        a, b = first["points"][out["joint"]], last["points"][out["joint"]]
        stroke_mm = math.hypot(a["x"] - b["x"], a["y"] - b["y"]) * 1000
        assert result(doc, "H") == pytest.approx(stroke_mm, abs=0.006)
    else:
        swing = abs((last["links"][out["link"]]["angle_deg"] - first["links"][out["link"]]["angle_deg"] + 180) % 360 - 180)
        md = markdown(doc, "t")
        assert f"ψ = {swing:.2f}°".replace(".", ",") in md
    # K from the crank angles of the extreme positions and the sense of rotation
    sense = -1 if crank.get("sense") == "cw" else 1
    working = (sense * (last["phi_deg"] - first["phi_deg"])) % 360
    assert result(doc, "K") == pytest.approx(working / (360 - working), abs=0.0006)
    assert result(doc, 'φ_"х.х"') == pytest.approx(360 - working, abs=0.006)
    # the table of all positions against `positions`
    t = table(doc, "linkage_positions")
    assert [row[0] for row in t.rows] == [p["label"] for p in pos]
    turning = [h for h in t.header if h.startswith("$ω_")]
    names = {ln.number: ln.name for ln in s1.mechanism.links}
    p0 = pos[0]
    for row, p in zip(t.rows, pos):
        assert value(row[1]) == pytest.approx(p["phi_deg"], abs=0.006)
        if out["kind"] == "slider":
            a, b = p["points"][out["joint"]], p0["points"][out["joint"]]
            assert value(row[2]) == pytest.approx(math.hypot(a["x"] - b["x"], a["y"] - b["y"]) * 1000, abs=0.006)
            speed = math.hypot(p["points"][out["joint"]]["vx"], p["points"][out["joint"]]["vy"])
            assert abs(value(row[3])) == pytest.approx(speed, abs=0.0006)
        else:
            assert abs(value(row[3])) == pytest.approx(abs(p["links"][out["link"]]["omega"]), abs=0.0006)
        for k, h in enumerate(turning):
            number = int(re.match(r"\$ω_(\d+)", h)[1])
            link = p["links"][names[number]]
            col = t.header.index(h)
            assert value(row[col]) == pytest.approx(link["omega"], abs=0.0006)
            assert value(row[col + 1]) == pytest.approx(link["epsilon"], abs=0.006)
    # the links' ω, ε in the position of the plans
    plan = data["plans"][0]["position"]
    w = table(doc, "linkage_omega")
    for row in w.rows:
        link = by_label[plan]["links"][row[1]]
        assert value(row[2]) == pytest.approx(link["omega"], rel=6e-4, abs=1e-12)
        assert value(row[3]) == pytest.approx(link["epsilon"], rel=6e-4, abs=1e-12)
    # the plans' scales as linkage.json gives them
    md = markdown(doc, "t")
    for kind, sym in (("velocity", "μ<sub>v</sub>"), ("acceleration", "μ<sub>a</sub>")):
        scale = data["plans"][0][kind]["scale"]
        assert f"{sym} = {scale:g}".replace(".", ",") in md


def check_claim(claim, s1):
    kind = claim["kind"]
    if kind == "linkage_dof":
        assert claim["dof"] == 3 * claim["n"] - 2 * claim["p5"] - claim["p4"]
        assert claim["n"] == len(s1.mechanism.links) and claim["p5"] == len(s1.mechanism.pairs)
    elif kind == "linkage_class":
        assert claim["mechanism_class"] == max(claim["classes"])
    elif kind == "linkage_position0":
        assert claim["rule"] in ("working", "load", "far", "given", "turning")
        if claim["rule"] == "working":  # the working stroke is the slower one
            assert s1.cycle.working > s1.cycle.returning
    elif kind == "linkage_time_ratio":
        assert claim["K"] == pytest.approx(claim["working_deg"] / claim["return_deg"], rel=1e-12)
        assert claim["working_deg"] + claim["return_deg"] == pytest.approx(360.0)
    elif kind == "linkage_plan_position":  # "in the middle of the working stroke": the nearest of the positions
        c = s1.cycle  # counted from the extreme where the working stroke starts, round the turn
        evens = [p for p in c.positions if p.label.isdigit()]
        lead = next((p.travel for p in c.positions if p.extreme == "start"), 0.0)

        def gap(p):
            d = (p.travel - lead - c.working / 2) % (2 * math.pi)
            return min(d, 2 * math.pi - d)
        nearest = min(evens, key=gap) if c.working is not None else None
        assert claim["middle"] == (nearest is not None and nearest.label == claim["label"])
        assert claim["label"] == s1.plans[0].position.label
    elif kind == "linkage_working_extremes":  # the working stroke runs start → end (position 0 elsewhere)
        assert s1.cycle.index(claim["start"]) is not None and s1.cycle.positions[s1.cycle.index(claim["start"])].extreme == "start"
        assert s1.cycle.positions[s1.cycle.index(claim["end"])].extreme == "end"
    elif kind == "linkage_pressure":
        assert claim["ok"] == (claim["worst_deg"] <= claim["limit_deg"])
    else:
        return False
    return True


@pytest.mark.parametrize("name", NAMES)
def test_every_claim_of_the_chapter_holds(name):
    doc = note(name)
    s1 = project(name).linkage.sheet1
    kinds = [c["kind"] for c in doc.claims if check_claim(c, s1)]
    assert {"linkage_dof", "linkage_class", "linkage_position0", "linkage_pressure", "linkage_plan_position"} <= set(kinds)


ENGLISH = re.compile(r"\b[A-Za-z]{3,}\b")


@pytest.mark.parametrize("name", NAMES)
def test_the_russian_chapter_speaks_russian(name):
    from tmm_cli.render.note.model import MATH, _texts

    doc = note(name)
    texts = [b.text for b in chapter_blocks(doc) if isinstance(b, Heading)]
    texts += [t for b in chapter_blocks(doc) for t in _texts(b)]
    body = MATH.sub(" ", doc.resolve("\n".join(texts)))
    assert not set(ENGLISH.findall(body)), sorted(set(ENGLISH.findall(body)))[:10]
    assert "--" not in body and "toml" not in body


def test_the_front_matter_names_the_four_sheets_and_takes_m_from_sheet_2():
    doc = note("shaper")
    md = markdown(doc, "t")
    front = md[:md.index("## Введение")]
    assert "лист 1 — структурный и кинематический анализ рычажного механизма" in front
    assert "лист 4 — синтез зубчатых механизмов" in front
    m = project("shaper").gears.torque_nm
    assert "момент M = " not in front.split("Исходные данные")[1].split("\n")[0]  # M is not given data …
    assert f"M = {m:.2f}".replace(".", ",") in front  # … but a result of sheet 2
    assert "РЫЧАЖНЫЙ МЕХАНИЗМ" in front
    intro = md[md.index("## Введение"):md.index("## 1 ")]
    assert "все четыре листа" in intro and "(лист 1)" in intro and "(лист 2)" in intro


def test_without_a_mechanism_the_note_has_no_chapter_1_of_the_linkage():
    r = run_project(get_variant("17"))
    doc = build_note(r, "ru", {})
    assert not any(isinstance(b, Heading) and b.label == "linkage" for b in doc.blocks)
    md = markdown(doc, "t")
    assert "лист 1" not in md and "Рычажный механизм" not in md and "Артоболевский" not in md
    assert "## 1 Синтез кулачкового механизма" in md


def test_a_vector_is_an_arrow_in_every_writer():
    src = "arrow(v)_(A3) = arrow(v)_(A2) + arrow(a)^k_(A3 A2)"
    assert to_text(parse(src), html=False).startswith("v\u20d7_(A3) = ")
    assert check_line(src) == []  # vectors are not numbers
    from lxml import etree

    xml = etree.tostring(omath_para(src)).decode()
    assert xml.count("m:acc>") >= 3 or xml.count(":acc>") >= 3


# ---------------------------------------------------------------------------------------------------
# the note's figure of the plans


@pytest.mark.parametrize("name", NAMES)
def test_the_plans_figure_fits_its_boxes_at_a_round_scale(name):
    from tmm_cli.render.figures import note_scales as S

    s1 = project(name).linkage.sheet1
    layout = S.linkage_layout(s1)
    pl = s1.plans[0]
    for kind, plan in (("velocity", pl.velocity), ("acceleration", pl.acceleration)):
        box = layout[kind]
        x, y = S.linkage_plan_axes(plan, box)
        assert x.mu == y.mu and x.mm == box.width and y.mm == box.height  # one scale, 1 mm of paper = μ
        mant = x.mu / 10 ** math.floor(math.log10(x.mu) + 1e-9)
        assert any(abs(mant - m) < 1e-9 for m in S.PLAN_SERIES)
        for z in plan.points.values():
            assert x.lo <= z.real <= x.hi and y.lo <= z.imag <= y.hi - S.LINKAGE_TITLE_MM * y.mu
        if layout.get("own"):  # drawn at sheet 1's μ, the one of the note's segment lengths
            assert x.mu == plan.scale
            continue
        # the next smaller round scale would not fit: the plan is drawn as large as the series allows
        smaller = max(m * 10 ** e for e in range(-6, 4) for m in S.PLAN_SERIES if m * 10 ** e < x.mu * (1 - 1e-9))
        xs, ys = [z.real for z in plan.points.values()], [z.imag for z in plan.points.values()]
        assert (max(xs) - min(xs)) * 1.16 / smaller > box.width or \
            (max(ys) - min(ys)) * 1.16 / smaller > box.height - S.LINKAGE_TITLE_MM


def test_project_with_a_mechanism_draws_the_plans_into_the_note(tmp_path):
    from click.testing import CliRunner

    from tmm_cli.cli import cli

    r = CliRunner().invoke(cli, ["project", "-v", "17", "--mechanism", str(EXAMPLES / "four_bar.toml"), "--no-sheets",
                                 "--report", "pdf", "--out", str(tmp_path), "--lang", "ru"])
    assert r.exit_code == 0, r.output
    folder = tmp_path / "variant-17"
    assert (folder / "note_linkage_plans.svg").is_file() and (folder / "note.pdf").is_file()
    typ = (folder / "note.typ").read_text(encoding="utf-8")
    assert typ.count("note_linkage_plans.svg") == 1
    assert typ.index("note_linkage_plans.svg") < typ.index("note_cam_motion.svg")  # in chapter 1, before the cam's


def test_an_offset_slot_has_the_pressure_angle_of_its_offset():
    """A slot at d from the pivot C: the block presses across the slot, the slotted link's point A
    moves across CA, so the pressure angle is arctan(d/t), t = √(|CA|² − d²) — largest where |CA| is
    least, |O1O2| − l_OA for a crank about O1 (a reviewer found «угол давления равен 0°» printed for
    every ВПВ group). Recomputed from the file's numbers, not from the code's pressure_angle."""
    data = tomllib.loads((EXAMPLES / "shaper_offset.toml").read_text(encoding="utf-8"))
    (x1, y1), (x2, y2) = data["frame"]["O1"], data["frame"]["O2"]
    d = data["group"][0]["offset"]
    ca_min = math.hypot(x2 - x1, y2 - y1) - data["crank"]["length"]
    expected = math.degrees(math.atan(abs(d) / math.sqrt(ca_min ** 2 - d ** 2)))
    s2 = analyse_linkage(data, "shaper_offset.toml")
    doc = build_note(run_project(get_variant("17"), linkage=s2, linkage_name="shaper_offset.toml"), "ru", {})
    (claim,) = [c for c in doc.claims if c["kind"] == "linkage_pressure" and c["group"] == 1]
    assert claim["worst_deg"] == pytest.approx(expected, abs=1e-6)
    text = "\n".join(b.text for b in doc.blocks if hasattr(b, "text") and isinstance(b.text, str))
    assert "угол давления равен 0°" not in text
    assert f"{expected:.2f}".replace(".", ",") + "°" in text
