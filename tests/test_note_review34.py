"""The strict teacher's reading of the notes of issue 34's mechanisms (/work/review/findings.md):
each finding as a test over every example mechanism, the numbers checked against what
`tmm linkage` exports (linkage.json), not against the code that wrote the note.

- A1: a piston's note says where its position 0 is (the dead centre nearest the head), never that
  it «turns fully and has no extreme positions».
- A2, C18: the crank's equation of moments names every reaction on the crank (R21 and R41 of a
  V compressor) with its sign; its terms, recomputed from the exported reactions, give M_ур.
- B5: no floating-point noise (3,8·10⁻¹⁷ м/с) is printed as a value.
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.linkage.sheet2 import analyse_sheet2
from tmm_cli.linkage.sheet2_file import parse_sheet2
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.markdown import markdown
from tmm_cli.render.note.mathsyntax import number_value
from tmm_cli.render.note.model import Formula, Heading
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NEW = ("shaper_offset", "rocking_block", "tangent", "scotch_yoke", "v_compressor")
OLD = ("shaper", "four_bar", "compressor", "whitworth")
GAS = ("v_compressor",)
_CACHE: dict = {}


def case(name: str, lang: str = "ru"):
    """(ProjectResult, the note's Document, its Markdown) of variant 17 with the example."""
    key = (name, lang)
    if key not in _CACHE:
        tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
        if name in ("compressor", "whitworth"):  # no [load] / a motor's speed: sheets 1-2 put beside the project
            m = parse_mechanism(tables, name)
            s2 = analyse_sheet2(analyse_mechanism(m), parse_sheet2(m))
            r = replace(run_project(get_variant("17")), linkage=s2)
        else:
            s2 = analyse_linkage(tables, f"{name}.toml")
            r = run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml")
        doc = build_note(r, lang, {})
        _CACHE[key] = (r, doc, markdown(doc, name))
    return _CACHE[key]


def exported(name: str) -> dict:
    """linkage.json as `tmm linkage` writes it."""
    key = ("json", name)
    if key not in _CACHE:
        import tempfile

        with tempfile.TemporaryDirectory() as folder:
            res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--no-plots", "--out", folder,
                                           "--lang", "ru"])
            assert res.exit_code == 0, res.output
            _CACHE[key] = json.loads((Path(folder) / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    return _CACHE[key]


def chapters(doc) -> list:
    """The blocks of the lever mechanism's two chapters."""
    out, inside = [], False
    for b in doc.blocks:
        if isinstance(b, Heading) and b.level == 1:
            inside = b.label in ("linkage", "dynamics")
        if inside:
            out.append(b)
    return out


def point(p: dict) -> complex:
    return complex(p["x"], p["y"])


def numbers(math_src: str) -> list[float]:
    """The printed numbers of a piece of typst math, in order ("274,09" → 274.09)."""
    out = []
    for m in re.finditer(r'"([^"]+)"|(?<![\w_])(\d+)(?![\w])', math_src):
        text = m.group(1) or m.group(2)
        v = number_value(text.replace("\u00a0", "").replace("\u202f", ""))
        if v is not None:
            out.append(v[0])
    return out


# --- A1 -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", GAS)
def test_a_piston_has_its_dead_centre_as_position_0(name):
    _, doc, md = case(name)
    assert "не имеет крайних положений" not in md
    assert "мёртвая точка" in md and "ближайшая к крышке цилиндра" in md
    claim = next(c for c in doc.claims if c["kind"] == "linkage_position0")
    assert claim["rule"] == "gas"
    # the position 0 of the JSON is where the piston is nearest its head
    data = exported(name)
    head = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))["load"][0]["head"]
    pin = data["output"]["joint"] if "joint" in data["output"] else None
    if pin is not None:
        dist = [abs(point(p["points"][pin]) - complex(*head)) for p in data["positions"]]
        assert dist[0] == pytest.approx(min(dist), abs=1e-9)


# --- A2, C18 ------------------------------------------------------------------------------------------


def crank_equation(doc) -> str:
    for b in chapters(doc):
        if isinstance(b, Formula) and b.math.startswith('M_"ур" = '):
            return b.math
    raise AssertionError("no equation of the crank's moments")


@pytest.mark.parametrize("name", NEW + ("shaper", "four_bar"))
def test_the_cranks_equation_has_every_reaction_on_it_with_its_sign(name):
    _, doc, md = case(name)
    data = exported(name)
    label = data["forces"]["position"]
    pos = next(p for p in data["positions"] if p["label"] == label)
    o = point(pos["points"][data["crank"]["pivot"]])
    mb = pos["balancing_moment_Nm"]
    # from the JSON: the moment about O of each reaction of a link k on the crank, R_k1 = −R_1k at its joint
    expected = []
    for key, part in pos["reaction_parts"].items():
        if part["links"][0] == 1:
            at = point(pos["points"][part["joint"]]) - o
            f = -complex(*pos["reactions"][key])
            moment = at.real * f.imag - at.imag * f.real
            if abs(moment) > 1e-9 * abs(mb):
                expected.append((part["links"][1], abs(f), moment))
    eq = crank_equation(doc)
    _, lhs, sub, res = [p.strip() for p in eq.replace(" \\ ", " ").split(" = ")][:4]
    for k, _, _ in expected:  # every reaction named, as R_k1 h_k1
        assert f"R_({k}1) h_({k}1)" in lhs, (k, lhs)
    # the substitution, term by term: −sign(M)·R·h
    terms = re.findall(r'([-+]?)\s*"?([\d,\u202f]+)"?\s*dot\s*"?([\d,]+)"?', sub)
    assert len(terms) == len(expected), sub
    for (sign, r, h), (k, size, moment) in zip(terms, expected):
        r_, h_ = (number_value(x.replace("\u202f", ""))[0] for x in (r, h))
        assert r_ == pytest.approx(size, rel=1e-4)
        assert (-1 if sign == "-" else 1) * r_ * h_ == pytest.approx(-moment, rel=2e-4, abs=1e-4)
    # the crank's own loads have no moment about O in these examples: the reactions alone give M_ур
    assert sum(-m for _, _, m in expected) == pytest.approx(mb, rel=1e-9, abs=1e-9)
    assert numbers(res)[0] == pytest.approx(mb, rel=5e-4)
    assert "plus.minus" not in eq and "±" not in md[md.index("Последним рассчитывается кривошип"):][:1500]


def test_the_v_compressor_names_both_rods_on_the_crank():
    _, doc, md = case("v_compressor")
    eq = crank_equation(doc)
    assert "R_(21) h_(21)" in eq and "R_(41) h_(41)" in eq
    assert "собственных нагрузок кривошипа" not in md  # its weight acts at O: no moment, no term


# --- B5 -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NEW + OLD)
def test_no_rounding_noise_is_printed_as_a_value(name):
    _, doc, md = case(name)
    # a power of ten below 10⁻⁹ is the computer's rounding in a mechanism whose sizes are centimetres
    assert not re.search(r"10⁻(⁹|[¹²³][⁰¹²³⁴⁵⁶⁷⁸⁹])", md), re.findall(r".{60}10⁻[⁰¹²³⁴⁵⁶⁷⁸⁹]+.{10}", md)


def test_the_yoke_at_rest_in_its_slot_prints_zero():
    """At φ = 90° (position 3, named by the file's `plan`: the default plans take a general position
    now) the yoke stands still, and its acceleration's rounding noise prints as 0."""
    tables = tomllib.loads((EXAMPLES / "scotch_yoke.toml").read_text(encoding="utf-8"))
    tables["plan"] = "3"
    s2 = analyse_linkage(tables, "scotch_yoke.toml")
    doc = build_note(run_project(get_variant("17"), linkage=s2, linkage_name="scotch_yoke.toml"), "ru", {})
    assert "Φ_3 = m_3 a_(S 3) = 12 dot 0 = 0" in " ".join(b.math for b in chapters(doc) if isinstance(b, Formula))


def test_the_zero_rule_in_one_place():
    """Below 10⁻⁹ of its kind's scale a number is 0; at 10⁻⁸ it is a value; no scale, no rule."""
    from types import SimpleNamespace as NS

    from tmm_cli.render.note.ctx import Ctx

    r, _, _ = case("scotch_yoke")
    c = Ctx(r, "ru")
    va = abs(r.linkage.sheet1.mechanism.crank.omega) * r.linkage.sheet1.mechanism.crank.length
    assert c.zero(3.847e-17, "m/s") == 0.0 and c.nz(-3.847e-17, "m/s", sig=4) == "0"
    assert c.zero(1e-8 * va, "m/s") == 1e-8 * va
    assert c.zero(1.183e-30, "N") == 0.0 and c.zero(0.002, "N") == 0.002
    assert Ctx(NS(linkage=None), "ru").zero(1e-30, "N") == 1e-30


# --- B3, C16: the slides' couples and the numbered vector equations of every group ---------------------


def formulas(doc) -> list:
    return [b for b in chapters(doc) if isinstance(b, Formula)]


@pytest.mark.parametrize("name", NEW + ("shaper", "four_bar"))
def test_every_group_has_its_numbered_vector_polygon_and_the_text_refers_to_it(name):
    r, doc, md = case(name)
    polys = {b.label: b for b in formulas(doc) if (b.label or "").startswith("dyn_poly_")}
    groups = r.linkage.sheet1.mechanism.groups
    assert sorted(polys) == sorted(f"dyn_poly_{g.index}" for g in groups)
    for b in polys.values():
        assert b.numbered
        assert not re.search(r"(?<!arrow\()\bR_", b.math.replace("arrow(R)_", "")), b.math  # every R an arrow
        assert "Σ F^" not in b.math, b.math
    for g in groups:  # the group's reactions cite their polygon's number
        assert any(f"{{eq:dyn_poly_{g.index}}}" in getattr(b, "text", "") for b in chapters(doc)), g.index


@pytest.mark.parametrize("name", ("tangent", "scotch_yoke", "rocking_block"))
def test_the_slides_couples_are_given_as_exported(name):
    """Every slide couple of linkage.json that is not zero is in the reactions' table with its value
    and has its equation of moments in the text, which gives the exported value."""
    _, doc, md = case(name)
    data = exported(name)
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    couples = {k: part["couple_Nm"] for k, part in pos["reaction_parts"].items()
               if part.get("couple_Nm") is not None and abs(part["couple_Nm"]) > 1e-9}
    assert couples, "an example of a slide on a moving link or a yoke carries a couple"
    rows = next(b for b in doc.blocks if getattr(b, "name", None) == "dyn_reactions").rows
    printed = {re.sub(r"[^0-9,]", "", row[0]): row[3] for row in rows if row[0].startswith("$M_(")}
    assert set(printed) == {k[1:] for k in couples}
    from tmm_cli.render.note.mathsyntax import number_value as nv

    for key, m in couples.items():
        value = nv(printed[key[1:]].split("\u00a0")[0])[0]
        assert value == pytest.approx(m, rel=5e-3, abs=1e-6)
        line = next(p for b in formulas(doc) for p in re.split(r"; quad | \\ ", b.math) if p.startswith(f"M_({key[1:]}) = "))
        assert numbers(line.split(" = ")[-1])[0] == pytest.approx(m, rel=5e-4, abs=1e-6), line
    if name == "scotch_yoke":  # the yoke's guide holds the block's push R23 at the height r·sin φ of A above Y
        r23 = complex(*pos["reactions"]["R23"])
        arm = 0.05 * abs(math.sin(math.radians(pos["phi_deg"])))
        assert abs(couples["R03"]) == pytest.approx(abs(r23) * arm, rel=1e-6)


# --- B4: a translating yoke has no Coriolis term; one block is one --------------------------------------


def test_the_scotch_yoke_translates_and_its_block_is_one():
    r, doc, md = case("scotch_yoke")
    data = exported("scotch_yoke")
    yoke = r.linkage.sheet1.mechanism.groups[-1].links[1]
    assert max(abs(p["links"][yoke]["omega"]) for p in data["positions"]) < 1e-9  # the yoke never turns
    assert "Камни" not in md and "кориолисовы составляющие" not in md
    assert "кулиса 3 движется поступательно" in md and "кориолисово ускорение камня относительно неё отсутствует" in md
    assert not any("a^k" in b.math for b in formulas(doc))


def test_the_tangent_has_one_coriolis_term_on_its_turning_guide():
    _, doc, md = case("tangent")
    assert "Камни скользят по вращающимся направляющим" not in md
    assert "Камень скользит по вращающейся направляющей звена 3" in md


# --- B8: a gas force is driving or resisting by the sign of its work ------------------------------------


def test_the_gas_forces_are_driving_or_resisting_as_their_pistons_move():
    _, doc, md = case("v_compressor")
    data = exported("v_compressor")
    k = next(j for j, p in enumerate(data["positions"]) if p["label"] == data["forces"]["position"])
    now, nxt = data["positions"][k], data["positions"][k + 1]
    rows = {row[0]: row[1] for row in next(b for b in doc.blocks if getattr(b, "name", None) == "dyn_loads").rows}
    for sym, f in now["applied_forces"].items():
        if not sym.startswith("P"):
            continue
        move = point(nxt["points"][f["at"]]) - point(now["points"][f["at"]])  # where the piston goes from here
        work = f["force"][0] * move.real + f["force"][1] * move.imag
        kind = rows[f"$P_{sym[1:]}$"]
        assert kind == ("движущая сила (давление газов)" if work > 0 else "сила сопротивления (давление газов)"), sym
    assert "полезное сопротивление" not in " ".join(rows.values())
    assert "приведённый момент сил сопротивления и сил тяжести" not in md
    assert "A<sub>с</sub> = A<sub>P 3</sub> + A<sub>P 5</sub>" in md


# --- C13, C20 ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NEW + ("shaper",))
def test_the_extremes_of_delta_t_are_at_delta_phi_and_the_last_row_is_360_0(name):
    _, doc, md = case(name)
    assert "наибольшее при Δ φ = " in md and "наибольшее при φ" not in md
    rows = next(b for b in doc.blocks if getattr(b, "name", None) == "dyn_reduced").rows
    assert rows[-1][1] == "360,0" and all(re.fullmatch(r"\d+,\d", row[1]) for row in rows)


# --- C21: decimals among decimals; a «;» after a reference survives typst ------------------------------------


def test_the_masses_table_has_no_powers_of_ten():
    r, doc, _ = case("shaper")
    rows = next(b for b in doc.blocks if getattr(b, "name", None) == "dyn_masses").rows
    assert rows and not any("10⁻" in cell for row in rows for cell in row)
    small = [ms for ms in r.linkage.input.masses if 0 < ms.J < 1e-3]
    from types import SimpleNamespace as NS

    from tmm_cli.render.note.ctx import Ctx

    assert Ctx(NS(linkage=None), "ru").n(6e-4, sig=4, sci=False) == "0,0006"
    for ms in small:
        assert any(cell.startswith("0,000") for row in rows for cell in row)


def test_a_semicolon_after_a_reference_is_kept_in_typst():
    """typst ends an embedded expression (#ref(<…>)) at a «;» and swallows it: «таблице 6 звенья»."""
    from tmm_cli.render.note.model import Document, Paragraph, Table
    from tmm_cli.render.note.typst import TypstWriter

    doc = Document("ru")
    doc.add(Table("dyn_masses", "Массы", ["a"], [["1"]]))
    doc.add(Paragraph("приведены в таблице {tab:dyn_masses}; звенья, не указанные в ней"))
    doc.number()
    w = TypstWriter(doc)
    src = "\n".join(w.block(doc.blocks[-1]))
    assert re.search(r"#ref\([^)]*\)\\; звенья", src), src


# --- C11: one role name per link; C12: the couple's second point has a letter of its own ----------------------


def _forms(role: str) -> list[str]:
    """The Russian nominative and genitive of a role's word."""
    from tmm_cli.i18n import tr, trc
    from tmm_cli.render.terminal.mechanism import ROLE_WORDS

    return [tr("ru", ROLE_WORDS[role]), trc("ru", "genitive", ROLE_WORDS[role])]


@pytest.mark.parametrize("name", NEW + ("shaper", "four_bar"))
def test_every_link_has_one_role_name_everywhere(name):
    from tmm_cli.linkage.roles import ROLES, link_roles

    r, doc, md = case(name)
    s1 = r.linkage.sheet1
    roles = link_roles(s1)
    text = md.lower()
    for ln in s1.mechanism.links:
        mine = roles[ln.name]
        assert f"| {ln.number} | {ln.name} | {_forms(mine)[0]} |" in md  # Table 1
        for other in ROLES:
            if other == mine or set(_forms(other)) & set(_forms(mine)):
                continue
            for word in _forms(other):
                for tag in (ln.name, str(ln.number)):
                    hit = re.search(rf"(?<![\w]){re.escape(word)} {re.escape(tag)}(?![\w′'])", text)
                    assert not hit, (ln.name, mine, text[max(0, hit.start() - 80):hit.end() + 40])


@pytest.mark.parametrize("name", ("tangent", "rocking_block"))
def test_the_couples_second_point_is_a_letter_of_its_own_on_the_note_and_the_sheet(name):
    from tmm_cli.render.sheets.dynamics_sheet import _lever_points

    r, doc, md = case(name)
    s2 = r.linkage
    mech = s2.sheet1.mechanism
    names = set(mech.joint_names) | {ln.name for ln in mech.links} | {p.name for p in mech.points}
    extra = [f for f in s2.lever.forces if f.point not in s2.sheet1.cycle.kin.z]
    assert extra  # a slider turning with its moving guide: its couple as two forces, one at a point of its own
    for f in extra:
        assert f.point not in names and f.point not in ("K", "L", "M", "N", "T", "V", "W"), f.point
        assert f.point.lower() in _lever_points(s2)  # sheet 2 draws its image under the same letter
        assert f"точкой {f.point.lower()} — концом луча p {f.point.lower()}" in md  # the note names it so
    assert "b′" not in md and "точкой \"b′\"" not in md
