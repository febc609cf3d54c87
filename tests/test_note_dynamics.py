"""Issue 25: the note's chapter on sheet 2 (render/note/dynamics_part.py) — the force analysis of one
position, Zhukovsky's lever, the dynamic model and the flywheel.

The note is built for variant 17 with each example mechanism that carries sheet 2 (shaper and
four_bar through `tmm project --mechanism`; the compressor, whose 1450 rpm no motor of sheet 4
drives, beside variant 17's own sheet 4). Then:

- the chapter is there, second after the front matter, before the cam;
- every "formula = substitution = result" reproduces (the checker of test_note_claims.py);
- its numbers agree with what `tmm linkage` writes (linkage.json, linkage_dynamics.csv), recomputed
  here another way: A_c from the load table of the TOML file (the area of its trapezoids times the
  stroke) and from ∫M_r dφ over the 0.5° grid, M = |A_c|/2π, the weights m·g from the TOML, the
  flywheel from ΔT − J_II·ω²/2 and δ, Wittenbauer's from its tangents, the Zhukovsky difference from
  the two moments, the reactions' magnitudes from their components;
- the claims the text makes hold;
- without a mechanism the note is what it was (the chapter adds nothing).
"""

from __future__ import annotations

import csv
import dataclasses
import json
import math
import re
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.markdown import markdown
from tmm_cli.render.note.mathsyntax import check_line, parse
from tmm_cli.render.note.model import Formula, Heading, Table, all_math
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ["shaper", "four_bar", "compressor"]
_CACHE: dict = {}


def tables(name):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


def case(name, lang="ru"):
    """(ProjectResult, Document, linkage.json, linkage_dynamics.csv rows) of variant 17 with `name`."""
    key = (name, lang)
    if key not in _CACHE:
        s2 = analyse_linkage(tables(name), f"{name}.toml")
        v = get_variant("17")
        if name == "compressor":  # 1450 rpm: sheet 4 has no motor for it; the chapter is sheet 2's alone
            r = dataclasses.replace(run_project(v), linkage=s2)
        else:
            r = run_project(v, linkage=s2, linkage_name=f"{name}.toml")
        _CACHE[key] = (r, build_note(r, lang, {}))
    return _CACHE[key]


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """linkage.json and linkage_dynamics.csv of each example, as `tmm linkage` writes them."""
    out = {}
    for name in NAMES:
        folder = tmp_path_factory.mktemp(name)
        res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--no-plots", "--out", str(folder)])
        assert res.exit_code == 0, res.output
        data = json.loads((folder / "linkage" / "linkage.json").read_text(encoding="utf-8"))
        with open(folder / "linkage" / "linkage_dynamics.csv", encoding="utf-8") as f:
            rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
        out[name] = (data, rows)
    return out


def number(text: str) -> float:
    """A number as the Russian note prints it."""
    text = text.replace("\u202f", "").replace("\u00a0", " ").replace(",", ".").replace("−", "-")
    return float(re.match(r"\s*(-?[\d.]+)", text).group(1))  # a unit may follow (issue 32: «1861,0 Н»)


def chapter_formulas(doc):
    """The display formulas of the chapter (between its heading and the next chapter)."""
    out, inside = [], False
    for b in doc.blocks:
        if isinstance(b, Heading) and b.level == 1:
            inside = b.label == "dynamics"
        elif inside and isinstance(b, Formula):
            out.append(b)
    return out


def result(doc, lhs: str) -> float:
    """The printed result of the formula piece that starts with `lhs` (``lhs = … = result``)."""
    for f in chapter_formulas(doc):
        pieces: list[str] = []
        for part in re.split(r"; quad | \\ ", f.math):
            if part.startswith("= ") and pieces:  # a long piece broken before an "="
                pieces[-1] += " " + part
            else:
                pieces.append(part)
        for piece in pieces:
            if piece.startswith(lhs + " ="):
                checks = check_line(piece)
                assert checks, piece
                return checks[-1].target
    raise AssertionError(f"no formula {lhs} in the chapter")


def table(doc, name) -> Table:
    return next(b for b in doc.blocks if isinstance(b, Table) and b.name == name)


# ---------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_the_chapter_is_second_and_every_substitution_reproduces(name):
    r, doc = case(name)
    heads = [b for b in doc.blocks if isinstance(b, Heading) and b.level == 1 and b.kind == "chapter"]
    labels = [h.label for h in heads]
    assert labels.index("dynamics") < labels.index("cam") < labels.index("gears")
    assert heads[labels.index("dynamics")].text == "Силовой анализ и динамика рычажного механизма"
    assert doc.off == []
    checked = 0
    for kind, src in all_math(doc):
        parse(src)
        if kind != "display":
            continue
        for c in check_line(src):
            checked += 1
            assert c.ok, f"{c.text} {c.relation} {c.target} in: {src}"
    dyn = sum(len(check_line(f.math)) for f in chapter_formulas(doc))
    assert dyn >= 15, dyn  # the chapter's own substitutions are many, and were checked above


def test_the_checker_sees_a_wrong_flywheel():
    """A substitution of the chapter's kind that does not reproduce is caught."""
    good = 'J_"I" = (Δ T_("I" max) - Δ T_("I" min))/(δ ω_1^2) = ("31,0144" - ("−215,218"))/("0,05" dot "6,2832"^2) = "124,74"'
    assert all(c.ok for c in check_line(good))
    assert not all(c.ok for c in check_line(good.replace('"124,74"', '"124,94"')))


@pytest.mark.parametrize("name", NAMES)
def test_the_work_and_the_driving_moment(name, written):
    """A_c = −H·(area of the load table), ∫M_r dφ over the grid gives it too; M = |A_c|/2π is the
    moment sheet 4 takes."""
    r, doc = case(name)
    data, rows = written[name]
    load = tables(name)["load"]
    values = load.get("force", load.get("moment"))
    x = load["stroke"]
    area = sum((x[k + 1] - x[k]) * (values[k] + values[k + 1]) / 2 for k in range(len(x) - 1))
    stroke = data["stroke_m"] if "force" in load else math.radians(data["swing_deg"])
    a_c = -stroke * area
    assert result(doc, 'A_"с"') == pytest.approx(a_c, rel=2e-4)
    # the trapezoid rule over the CSV's 0.5° grid (the jumps of the load cost it a little)
    integral = sum((b["travel_deg"] - a["travel_deg"]) * math.pi / 180 * (a["M_r_Nm"] + b["M_r_Nm"]) / 2
                   for a, b in zip(rows, rows[1:]))
    assert integral == pytest.approx(a_c, rel=2e-2)
    m = abs(a_c) / (2 * math.pi)
    assert result(doc, 'M_"д"') == pytest.approx(m, rel=2e-4)
    assert data["dynamics"]["motor_moment_Nm"] == pytest.approx(m, rel=1e-9)
    if name != "compressor":  # the gears chapter's power uses this M
        assert r.gears.torque_nm == pytest.approx(m, rel=1e-9)
        gears_power = [src for kind, src in all_math(doc) if kind == "display" and src.startswith('N_"д"')]
        assert gears_power and f'"{f"{m:.5g}".replace(".", ",")}"' in gears_power[0]


@pytest.mark.parametrize("name", NAMES)
def test_the_loads_of_the_position(name, written):
    """G = m·g from the TOML's masses; Φ and M_Φ as the JSON's applied forces of the position."""
    r, doc = case(name)
    data, _ = written[name]
    masses = tables(name)["mass"]
    number_of = {ms.m: ms.number for ms in r.linkage.input.masses}
    for ms in masses:
        k = number_of[ms["m"]]
        assert result(doc, f"G_{k}") == pytest.approx(ms["m"] * 9.81, rel=5e-4)
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    for sym, f in pos["applied_forces"].items():
        if sym.startswith("Φ"):
            assert result(doc, f"Φ_{sym[1:]}") == pytest.approx(math.hypot(*f["force"]), rel=5e-4)
    for sym, m in pos["applied_moments_Nm"].items():
        if sym.startswith("MΦ"):
            assert result(doc, f"M_(Φ {sym[2:]})") == pytest.approx(abs(m), rel=5e-4)


@pytest.mark.parametrize("name", NAMES)
def test_the_reactions_and_the_balancing_moment(name, written):
    r, doc = case(name)
    data, _ = written[name]
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    rows = table(doc, "dyn_reactions").rows
    printed = {re.sub(r"[^0-9,]", "", row[0]): number(row[3]) for row in rows[:-1]}
    assert set(printed) == {k[1:] for k in pos["reactions"]}
    for key, (rx, ry) in pos["reactions"].items():
        assert printed[key[1:]] == pytest.approx(math.hypot(rx, ry), abs=0.051)
    mb = pos["balancing_moment_Nm"]
    assert number(rows[-1][3]) == pytest.approx(mb, abs=0.0051)
    assert result(doc, 'M_"ур"') == pytest.approx(mb, rel=5e-4)  # with its sign (counter-clockwise positive)
    # the tangential components of the groups from the JSON's parts
    for key, part in pos["reaction_parts"].items():
        if part.get("tangential") is not None:
            sym = f"R_({key[1:]})^τ"
            assert result(doc, sym) == pytest.approx(math.hypot(*part["tangential"]), rel=5e-4, abs=1e-6)
    claim = next(c for c in doc.claims if c["kind"] == "linkage_balancing_sense")
    omega = data["crank"]["omega_rad_s"] if "omega_rad_s" in data["crank"] else r.linkage.sheet1.cycle.kin.omega1
    assert claim["drives"] == (mb * omega > 0)


@pytest.mark.parametrize("name", NAMES)
def test_zhukovsky(name, written):
    r, doc = case(name)
    data, _ = written[name]
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    mb, mz = pos["balancing_moment_Nm"], pos["zhukovsky_moment_Nm"]
    assert result(doc, 'M_"ур"^"Ж"') == pytest.approx(abs(mz), rel=5e-4)
    diff = (abs(mb) - abs(mz)) / abs(mb) * 100
    # the difference to the digits the program has (issue 32: not «0,00 %»): two significant digits,
    # below 10⁻⁹ % (the computer's rounding) the bound «< 10⁻⁹ %»
    math_ = next(f.math for f in chapter_formulas(doc) if f.math.startswith("Δ ="))
    rel, shown = re.search(r'dot 100 ([=<]) ("[^"]+"|\S+) thin', math_).groups()
    diff = pos["zhukovsky_difference_pct"] * (1 if mb > 0 else -1)  # the moments in the JSON are rounded
    if 0.0 < abs(diff) < 1e-9:
        assert (rel, shown) == ("<", "10^(-9)")
    else:
        assert rel == "=" and number(shown.strip('"')) == pytest.approx(diff, rel=0.05, abs=1e-12)
    # the lever's table: the moments about the pole add up to F_b·pa
    rows = table(doc, "dyn_lever").rows
    total = number(rows[-1][-1])
    assert sum(number(row[-1]) for row in rows[:-1]) == pytest.approx(total, abs=0.06 * len(rows))
    claim = next(c for c in doc.claims if c["kind"] == "linkage_zhukovsky")
    assert claim["ok"] == (abs(diff) < 1.0) and claim["ok"]


@pytest.mark.parametrize("name", NAMES)
def test_the_flywheel(name, written):
    """Mertsalov's J from the CSV's ΔT and J_II, ω_m and δ; Wittenbauer's from its tangents; the disc
    or rim from J; the claim that a flywheel is needed."""
    r, doc = case(name)
    data, rows = written[name]
    dyn = data["dynamics"]
    w, delta = dyn["omega_mean"], dyn["delta"]
    dT_I = [row["dT_J"] - row["J_II_kgm2"] * w * w / 2 for row in rows]
    J_I = (max(dT_I) - min(dT_I)) / (delta * w * w)
    assert result(doc, 'J_"I"') == pytest.approx(J_I, rel=5e-4)
    J_fl = J_I - dyn["crank_rotor_inertia_kgm2"]
    assert result(doc, 'J_"м"') == pytest.approx(J_fl, rel=5e-4)
    assert J_fl == pytest.approx(dyn["flywheel_inertia_kgm2"], rel=1e-6)
    # Wittenbauer: the tangents of slopes ω_max²/2, ω_min²/2 to the curve (J_r, ΔT)
    k_max, k_min = (w * (1 + delta / 2)) ** 2 / 2, (w * (1 - delta / 2)) ** 2 / 2
    c_max = max(row["dT_J"] - k_max * row["J_r_kgm2"] for row in rows)
    c_min = min(row["dT_J"] - k_min * row["J_r_kgm2"] for row in rows)
    assert result(doc, 'J_"м"^"В"') == pytest.approx((c_max - c_min) / (k_max - k_min), rel=5e-4)
    claim = next(c for c in doc.claims if c["kind"] == "linkage_flywheel")
    assert claim["needed"] == (J_fl > 0)
    size = dyn["flywheel"]
    rho = tables(name)["dynamics"].get("density", 7800.0)
    D = result(doc, "D")
    assert D == pytest.approx(size["diameter_m"], rel=5e-4)
    if size["kind"] == "disc":  # J = m·D²/8 with m = ρ·π·D²·b/4
        assert rho * math.pi * D ** 2 * size["width_m"] / 4 * D ** 2 / 8 == pytest.approx(J_fl, rel=3e-3)
    else:  # J = m·D²/4 with m = ρ·π·D·b·h
        assert rho * math.pi * D * size["width_m"] * size["thickness_m"] * D ** 2 / 4 == pytest.approx(J_fl, rel=3e-3)
    assert result(doc, "m") == pytest.approx(size["mass_kg"], rel=5e-4)
    actual = next(c for c in doc.claims if c["kind"] == "linkage_delta_actual")
    assert abs(actual["actual"] - delta) < 0.05 * delta  # the flywheel holds the speed as asked


def test_the_reduced_table_is_the_csvs(written):
    """Table of M_пр, J_пр, A_с, ΔT at the positions: the CSV's values at the positions' travels."""
    r, doc = case("shaper")
    data, rows = written["shaper"]
    by_travel = {round(row["travel_deg"], 6): row for row in rows}
    for row in table(doc, "dyn_reduced").rows:
        travel = number(row[1])
        if round(travel, 6) not in by_travel:
            continue  # an extreme position between grid nodes
        ref = by_travel[round(travel, 6)]
        assert number(row[2]) == pytest.approx(ref["M_r_Nm"], abs=0.0051)
        assert number(row[4]) == pytest.approx(ref["A_r_J"], abs=0.0051)
        assert number(row[5]) == pytest.approx(ref["dT_J"], abs=0.0051)


def test_english_chapter():
    r, doc = case("four_bar", "en")
    md = markdown(doc, "t")
    assert "Force analysis and dynamics of the lever mechanism" in md and "Zhukovsky" in md
    assert not re.search(r"[А-Яа-я]{5,}", md[md.index("Force analysis and dynamics"):md.index("Synthesis of the cam")])


# ---------------------------------------------------------------------------------------------------
# without a mechanism


def test_without_a_mechanism_the_note_is_unchanged(monkeypatch):
    """The chapter says nothing when the project has no mechanism: the note is the one built without
    the chapter at all, word for word (report.md of variant 17)."""
    import tmm_cli.render.note as note

    r = run_project(get_variant("17"))
    with_chapter = markdown(build_note(r, "ru", {}), "t")
    chapters = note._chapters()
    monkeypatch.setattr(note, "_chapters", lambda: tuple(ch for ch in chapters if ch.__name__ != "dynamics_chapter"))
    without = markdown(build_note(r, "ru", {}), "t")
    assert with_chapter == without
    assert "Силовой" not in with_chapter and "Артоболевский" not in with_chapter


def test_the_project_command_writes_the_chapter(tmp_path):
    res = CliRunner().invoke(cli, ["project", "-v", "17", "--mechanism", str(EXAMPLES / "shaper.toml"), "--no-plots",
                                   "--report", "md", "--no-sheets", "--out", str(tmp_path), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    md = (tmp_path / "variant-17" / "report.md").read_text(encoding="utf-8")
    assert "## 2 Силовой анализ и динамика рычажного механизма" in md  # after sheet 1's chapter
    assert "Артоболевский, И. И." in md  # the cited source is listed
    assert md.index("рычагу Жуковского") < md.index("Момент инерции маховика") < md.index("Синтез кулачкового")


# ---------------------------------------------------------------------------------------------------
# the documents


@pytest.mark.parametrize("name", ["shaper", "four_bar"])
def test_pdf_and_docx_carry_the_chapter(name, tmp_path):
    """note.pdf (typst) and note.docx of the project with the chapter: both written, the chapter's
    headings and numbers in them, the DOCX valid OOXML, no typst syntax left in the PDF's text."""
    pypdf = pytest.importorskip("pypdf")
    import docx

    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.note import write_note
    from test_note import _audit, _squash, _text

    r, _ = case(name)
    write_note(tmp_path, r, "ru", TitleFields(), {}, docx=True, pdf=True)
    text = _text(tmp_path / "note.pdf")
    flat = _squash(text)
    assert "Силовойанализидинамикарычажногомеханизма" in flat and "рычагуЖуковского" in flat
    assert "Артоболевский,И.И." in flat
    assert not re.search(r"[^\W_]_[^\W_(]|[^\W_]_\(", text)
    numbers = [int(n) for n in re.findall(r"\s\((\d{1,3})\)\s*$", text, flags=re.M)]  # a space before: not a superscript (2) of ΣM
    assert numbers[:3] == [1, 2, 3] and len(numbers) == len(set(numbers))
    m = abs(r.linkage.dynamics.M_d)
    assert f"{m:.2f}".replace(".", ",") in text
    d = docx.Document(str(tmp_path / "note.docx"))
    body = "\n".join(p.text for p in d.paragraphs).replace("\u2060", "")
    assert "Силовой анализ и динамика рычажного механизма" in body and "Момент инерции маховика" in body
    _audit(tmp_path / "note.docx")
    assert len(pypdf.PdfReader(tmp_path / "note.pdf").pages) > 20


# ---------------------------------------------------------------------------------------------------
# other mechanism files: the chapter says what it has, and its substitutions still reproduce


def _variant(name, change):
    t = tables(name)
    change(t)
    return t


def _no_dynamics(t):
    del t["dynamics"]


def _no_gravity_no_masses(t):
    t["gravity"] = False
    del t["mass"]


def _crank_off_centre(t):  # the crank's centre of mass on OA: its weight and inertia force turn it
    t["point"] = t.get("point", []) + [{"name": "S1", "link": ["O", "A"], "along": 0.03}]
    t["mass"][0]["centre"] = "S1"


def _return_stroke(t):  # the plans' position on the return stroke: no useful resistance there
    t["plan"] = "9"


VARIANTS = [("four_bar", _no_dynamics), ("shaper", _no_gravity_no_masses), ("four_bar", _crank_off_centre),
            ("compressor", _crank_off_centre), ("shaper", _return_stroke)]


@pytest.mark.parametrize("name,change", VARIANTS, ids=[f"{n}-{c.__name__.strip('_')}" for n, c in VARIANTS])
def test_other_files(name, change):
    s2 = analyse_linkage(_variant(name, change), f"{name}.toml")
    r = dataclasses.replace(run_project(get_variant("17")), linkage=s2)
    doc = build_note(r, "ru", {})
    assert doc.off == []
    for f in chapter_formulas(doc):
        for c in check_line(f.math):
            assert c.ok, f"{c.text} {c.relation} {c.target} in: {f.math}"
    md = markdown(doc, "t")
    chapter = md[md.index("Силовой анализ и динамика"):md.index("Синтез кулачкового")]
    i = s2.force_position
    assert result(doc, 'M_"ур"') == pytest.approx(float(s2.balancing[i]), rel=5e-4)
    if change is _no_dynamics:
        assert "маховик не рассчитывается" in chapter and "Мерцалова" not in chapter
    if change is _no_gravity_no_masses:
        assert "Силы тяжести" not in chapter and "Силы инерции приложены" not in chapter
    if change is _return_stroke:
        assert "совершает холостой ход" in chapter and "F<sub>пс</sub> = 0" in chapter
        assert float(s2.balancing[i]) * s2.sheet1.cycle.kin.omega1 != 0


# ---------------------------------------------------------------------------------------------------
# the note's figure of sheet 2


def test_the_dynamics_figure_is_drawn_only_with_a_mechanism():
    from tmm_cli.render.note import NOTE_FIGURES, note_figures

    r, _ = case("shaper")
    assert note_figures(r) == ("linkage_plans", "linkage_dynamics") + NOTE_FIGURES  # the chapters' order
    assert note_figures(run_project(get_variant("17"))) == NOTE_FIGURES


@pytest.mark.parametrize("name", NAMES)
def test_the_dynamics_figure_at_round_scales(name):
    """Each diagram at a round μ (1, 2, 2,5, 4, 5 × 10^k) that holds its curve; the turn at 2,5 °/mm
    on 144 mm; no text under 10 pt on paper."""
    from matplotlib.text import Text

    from tmm_cli.render.figures import note_scales as S
    from tmm_cli.render.figures.note import MIN_PT, note_figure, note_style

    r, _ = case(name)
    d = r.linkage.dynamics
    sc = S.dynamics_scales(r.linkage)
    assert sc.phi.mu * sc.phi.mm == pytest.approx(360.0) and sc.phi.mm <= S.DYNAMICS["x"][1]
    for axis, lo, hi in ((sc.M, min(d.M_r.min(), d.M_d), max(d.M_r.max(), d.M_d)), (sc.T, d.dT.min(), d.dT.max()),
                         (sc.J, d.J_r.min(), d.J_r.max())):
        mantissa = axis.mu / 10 ** math.floor(math.log10(axis.mu))
        assert any(abs(mantissa - m) < 1e-9 for m in (1, 2, 2.5, 4, 5)), axis.mu
        assert axis.lo <= lo and hi <= axis.hi and axis.mm == S.DYNAMICS["panel"]
    with note_style():
        fig = note_figure(r, "ru", "linkage_dynamics")
        texts = [t for t in fig.findobj(Text) if t.get_text()]
        assert all(t.get_fontsize() >= MIN_PT for t in texts)
        words = " ".join(t.get_text() for t in texts)
        assert "положения кривошипа" in words and "пр" in words
        w, h = fig.get_size_inches()
        assert (w * 2.54, h * 2.54) == pytest.approx(S.figure_size_cm("linkage_dynamics"), abs=0.01)


def test_the_project_draws_it_into_the_note(tmp_path):
    res = CliRunner().invoke(cli, ["project", "-v", "17", "--mechanism", str(EXAMPLES / "four_bar.toml"), "--no-sheets",
                                   "--report", "pdf", "--out", str(tmp_path), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    folder = tmp_path / "variant-17"
    assert (folder / "note_linkage_dynamics.svg").is_file()
    typ = (folder / "note.typ").read_text(encoding="utf-8")
    assert typ.count("note_linkage_dynamics.svg") == 1
    assert typ.index("note_linkage_dynamics.svg") < typ.index("note_cam_motion.svg")
