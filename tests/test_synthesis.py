"""`tmm synth` (issue 33): every synthesised mechanism, written as a mechanism file and analysed by
`tmm linkage`'s own core (parsed from the text, as `tmm linkage` reads it), gives the task's H and K
to 0.1 %, ψ to 0.05° and γ_min at least the task's — over random feasible tasks of each type; the
closed forms against independent constructions; hostile and infeasible tasks refused in one line
naming the key; the chain synth → linkage → project --mechanism."""

import cmath
import json
import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from cli_helpers import assert_one_line_error, run
from tmm_cli.errors import TmmError
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.positions import cycle
from tmm_cli.linkage.synthesis import (
    crank_rocker,
    crank_slider_offset,
    offset_limit,
    theta_of,
    transmission_min,
)
from tmm_cli.linkage.synthesis_file import synthesised_file
from tmm_cli.linkage.synthesis_task import parse_task, synthesise

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
PROPS = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def analysed(task: dict):
    """The task synthesised, its file's text parsed and analysed as `tmm linkage` does:
    (synthesis, H or ψ, K, γ_min [deg])."""
    t = parse_task(task)
    syn = synthesise(t)
    text = synthesised_file(syn, t).text
    c = cycle(parse_mechanism(tomllib.loads(text), "synth"))
    gamma = 90.0 - max(math.degrees(p.worst) for p in c.pressure)
    return syn, c.stroke, c.time_ratio, gamma


def _close(x, want, rtol):
    return abs(x - want) <= rtol * abs(want)


# ---------------------------------------------------------------------------------------------------
# properties over random feasible tasks

@PROPS
@given(h=st.floats(0.02, 1.0), lam=st.floats(0.1, 0.5))
def test_central_crank_slider(h, lam):
    syn, stroke, k, _ = analysed({"type": "crank-slider", "stroke": h, "lambda": lam})
    assert _close(stroke, h, 1e-3) and _close(k, 1.0, 1e-3)
    assert syn.rod == pytest.approx(syn.crank / lam, rel=1e-12)


@PROPS
@given(h=st.floats(0.02, 1.0), k=st.floats(1.02, 2.6), frac=st.floats(0.02, 0.9))
def test_offset_crank_slider_by_k(h, k, frac):
    e = frac * offset_limit(h, theta_of(k))
    assume(e <= 100.0)
    _, stroke, k_found, _ = analysed({"type": "crank-slider", "stroke": h, "time_ratio": k, "offset": e})
    assert _close(stroke, h, 1e-3) and _close(k_found, k, 1e-3)


@PROPS
@given(h=st.floats(0.02, 1.0), lam=st.floats(0.1, 0.45), frac=st.floats(0.0, 0.6))
def test_offset_crank_slider_by_lambda(h, lam, frac):
    e = frac * h
    try:
        syn, stroke, k, _ = analysed({"type": "crank-slider", "stroke": h, "lambda": lam, "offset": e})
    except TmmError as exc:  # a large offset with a small stroke: refused, naming the offset
        assert "'offset'" in str(exc)
        assume(False)
    assert _close(stroke, h, 1e-3) and _close(k, syn.time_ratio, 1e-3) and syn.lam == pytest.approx(lam)


@PROPS
@given(c=st.floats(0.05, 1.0), psi=st.floats(10.0, 110.0), k=st.floats(1.02, 1.9), frac=st.floats(0.3, 1.0))
def test_crank_rocker_by_transmission(c, psi, k, frac):
    best = math.degrees(crank_rocker(c, math.radians(psi), k).gamma_best)
    gamma = frac * best
    assume(gamma > 1.0)
    syn, swing, k_found, g = analysed({"type": "crank-rocker", "rocker": c, "swing_deg": psi, "time_ratio": k,
                                        "min_transmission_deg": gamma})
    assert abs(math.degrees(swing) - psi) <= 0.05 and _close(k_found, k, 1e-3)
    assert g >= gamma - 1e-6 and g == pytest.approx(math.degrees(syn.gamma_min), abs=1e-6)


@PROPS
@given(c=st.floats(0.05, 1.0), psi=st.floats(10.0, 110.0), k=st.floats(1.02, 1.9), stretch=st.floats(-0.15, 0.15))
def test_crank_rocker_by_frame(c, psi, k, stretch):
    frame = crank_rocker(c, math.radians(psi), k).frame * (1.0 + stretch)
    try:
        syn, swing, k_found, g = analysed({"type": "crank-rocker", "rocker": c, "swing_deg": psi, "time_ratio": k,
                                            "frame": frame})
    except TmmError as exc:
        assert "'frame'" in str(exc)
        assume(False)
    assert syn.frame == pytest.approx(frame, rel=1e-9)
    assert abs(math.degrees(swing) - psi) <= 0.05 and _close(k_found, k, 1e-3)
    assert g == pytest.approx(math.degrees(syn.gamma_min), abs=1e-6)


@PROPS
@given(h=st.floats(0.05, 1.0), k=st.floats(1.05, 2.5), frame=st.floats(0.1, 1.0), ratio=st.floats(0.2, 0.6))
def test_slotted_link(h, k, frame, ratio):
    syn, stroke, k_found, g = analysed({"type": "slotted-link", "stroke": h, "time_ratio": k, "frame": frame,
                                        "rod_ratio": ratio})
    assert _close(stroke, h, 1e-3) and _close(k_found, k, 1e-3)
    assert g == pytest.approx(90.0 - math.degrees(syn.rod_angle), abs=1e-6)  # the guide through the sagitta's middle


# ---------------------------------------------------------------------------------------------------
# the closed forms against independent constructions

def test_offset_slider_triangle_by_construction():
    """The triangle O B₁ B₂ drawn from the lengths found: the angle at O is θ, the height is e, B₁B₂ = H."""
    s = crank_slider_offset(0.10, 1.2, 0.02)
    b1, b2 = complex(math.sqrt(s.far ** 2 - 0.02 ** 2), -0.02), complex(math.sqrt(s.near ** 2 - 0.02 ** 2), -0.02)
    assert abs(b1 - b2) == pytest.approx(0.10, rel=1e-12)
    assert abs(cmath.phase(b2 / b1)) == pytest.approx(math.radians(180.0 * 0.2 / 2.2), rel=1e-12)


def test_rocker_pivot_sees_the_chord_at_theta_and_the_transmission_angle_matches_linkage():
    s = crank_rocker(0.20, math.radians(40.0), 1.2, frame=0.30)
    assert abs(cmath.phase((s.C2 - s.A) / (s.C1 - s.A))) == pytest.approx(theta_of(1.2), abs=1e-9)
    assert abs(s.C1 - s.D) == pytest.approx(0.20) and abs(s.C2 - s.D) == pytest.approx(0.20)
    assert abs(s.A - s.centre) == pytest.approx(s.radius) and abs(s.C1 - s.centre) == pytest.approx(s.radius)
    # docs/examples/four_bar.toml: γ_min by the closed form = 90° − tmm linkage's worst pressure angle
    c = cycle(parse_mechanism(tomllib.loads((EXAMPLES / "four_bar.toml").read_text(encoding="utf-8"))))
    assert math.degrees(transmission_min(0.08, 0.28, 0.20, 0.30)) == pytest.approx(
        90.0 - math.degrees(c.pressure[0].worst), abs=1e-6)


def test_the_best_pivot_beats_every_other_point_of_the_locus():
    s = crank_rocker(0.20, math.radians(40.0), 1.2)
    for frame in (0.15, 0.20, 0.25, 0.30, 0.40, 0.60):
        try:
            other = crank_rocker(0.20, math.radians(40.0), 1.2, frame=frame)
        except TmmError:
            continue
        assert other.gamma_min <= s.gamma_min + 1e-6


def test_the_mechanism_file_records_its_task_and_copies_the_optional_tables():
    t = parse_task(tomllib.loads((EXAMPLES / "synth_shaper.toml").read_text(encoding="utf-8")))
    data = tomllib.loads(synthesised_file(synthesise(t), t).text)
    assert data["synthesis"] == {"type": "slotted-link", "stroke": 0.4, "time_ratio": 1.5, "frame": 0.3, "rod_ratio": 0.3}
    assert data["crank"]["rpm"] == 60 and data["crank"]["sense"] == "cw" and data["gravity"] is True
    assert len(data["mass"]) == 5 and data["load"]["working"] == "towards" and data["dynamics"]["delta"] == 0.05
    assert parse_mechanism(data).extra["synthesis"]["type"] == "slotted-link"


def test_a_working_stroke_named_by_the_load_stays_the_slow_one():
    base = {"type": "crank-slider", "stroke": 0.1, "time_ratio": 1.3, "offset": 0.02, "rpm": 100}
    for working in ("away", "towards"):
        _, stroke, k, _ = analysed({**base, "load": {"on": "B", "stroke": [0, 1], "force": [10, 10], "working": working}})
        assert k == pytest.approx(1.3, rel=1e-3)


# ---------------------------------------------------------------------------------------------------
# the command

def test_command_json_and_files(tmp_path):
    r = run("synth", EXAMPLES / "synth_rocker.toml", "--out", tmp_path, "--json", "--no-plots", "--lang", "en")
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    assert {"lengths", "checks", "mechanism_toml"} <= set(doc)
    assert all(c["ok"] for c in doc["checks"].values())
    assert doc["checks"]["swing_deg"]["linkage"] == pytest.approx(40.0, abs=0.05)
    assert (tmp_path / "synth_rocker.toml").read_text(encoding="utf-8") == doc["mechanism_toml"]
    data = tomllib.loads(doc["mechanism_toml"])
    assert data["crank"]["length"] == pytest.approx(doc["lengths"]["l_AB_m"], rel=1e-12)
    assert data["group"][0]["lengths"] == pytest.approx([doc["lengths"]["l_BC_m"], 0.20])


def test_command_terminal_in_russian_with_the_figure(tmp_path):
    r = run("synth", EXAMPLES / "synth_slider.toml", "--out", tmp_path, "--lang", "ru")
    assert r.exit_code == 0, r.output
    assert "l_OA = ½·√(H² − 2·H·e·tg(θ/2))" in r.stdout and "48,54" in r.stdout
    assert (tmp_path / "synth_slider_construction.png").stat().st_size > 10_000


def test_the_task_file_is_never_overwritten(tmp_path):
    task = tmp_path / "t.toml"
    task.write_text('type = "crank-slider"\nstroke = 0.1\nlambda = 0.25\n', encoding="utf-8")
    r = run("synth", task, "--out", tmp_path, "--no-plots", "--lang", "en")
    assert_one_line_error(r, "--out")
    assert task.read_text(encoding="utf-8").startswith('type = "crank-slider"')


@pytest.mark.parametrize("name,k,rpm", [("synth_shaper", 1.5, 60.0), ("synth_rocker", 1.2, 120.0),
                                         ("synth_slider", 1.2, 90.0)])
def test_chain_synth_linkage_project(name, k, rpm, tmp_path):
    """The README's chain works end to end for every shipped example: the task's sheet-2 tables reach
    the mechanism file, and the project's note opens chapter 1 with the synthesis."""
    r = run("synth", EXAMPLES / f"{name}.toml", "--out", tmp_path / "m", "--no-plots", "--lang", "en")
    assert r.exit_code == 0, r.output
    mech = tmp_path / "m" / f"{name}.toml"
    r = run("linkage", mech, "--out", tmp_path, "--json", "--no-plots", "--lang", "en")
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    assert doc["time_ratio"] == pytest.approx(k, rel=1e-3)
    if name == "synth_shaper":
        assert doc["stroke_m"] == pytest.approx(0.40, rel=1e-3)
    r = run("project", "-v", 17, "--mechanism", mech, "--no-plots", "--report", "md", "--no-sheets", "--out",
            tmp_path / "p", "--lang", "ru")
    assert r.exit_code == 0, r.output
    res = json.loads((tmp_path / "p" / "variant-17" / "results.json").read_text(encoding="utf-8"))
    assert res["gears"]["crank_rpm"] == pytest.approx(rpm)
    assert res["mechanism"]["dynamics"]["motor_moment_Nm"] > 0
    assert "Синтез механизма" in (tmp_path / "p" / "variant-17" / "report.md").read_text(encoding="utf-8")


HOSTILE = {
    "K = 1, slotted link": ('type = "slotted-link"\nstroke = 0.4\ntime_ratio = 1.0\nframe = 0.3\n', "'time_ratio'"),
    "K < 1, rocker": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 0.8\nframe = 0.3\n', "'time_ratio'"),
    "ψ = 180": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 180\ntime_ratio = 1.2\nframe = 0.3\n', "'swing_deg'"),
    "ψ > 180": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 200\ntime_ratio = 1.2\nframe = 0.3\n', "'swing_deg'"),
    "NaN": ('type = "slotted-link"\nstroke = nan\ntime_ratio = 1.5\nframe = 0.3\n', "'stroke'"),
    "inf K": ('type = "slotted-link"\nstroke = 0.4\ntime_ratio = inf\nframe = 0.3\n', "'time_ratio'"),
    "negative length": ('type = "crank-rocker"\nrocker = -0.2\nswing_deg = 40\ntime_ratio = 1.2\nframe = 0.3\n', "'rocker'"),
    "negative offset": ('type = "crank-slider"\nstroke = 0.1\ntime_ratio = 1.2\noffset = -0.02\n', "'offset'"),
    "text": ('type = "crank-slider"\nstroke = "big"\nlambda = 0.25\n', "'stroke'"),
    "K ≥ 3 slider": ('type = "crank-slider"\nstroke = 0.1\ntime_ratio = 3.5\noffset = 0.02\n', "'time_ratio'"),
    "offset too large": ('type = "crank-slider"\nstroke = 0.1\ntime_ratio = 2.0\noffset = 0.2\n', "'offset'"),
    "λ ≥ 1": ('type = "crank-slider"\nstroke = 0.1\nlambda = 1.5\n', "'lambda'"),
    "γ unreachable": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 100\ntime_ratio = 1.8\n'
                      'min_transmission_deg = 80\n', "'min_transmission_deg'"),
    "frame off the locus": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 1.2\nframe = 5.0\n',
                            "'frame'"),
    "no frame nor γ": ('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 1.2\n', "'frame'"),
    "unknown type": ('type = "cam"\nstroke = 0.1\n', "'type'"),
    "unknown key": ('type = "slotted-link"\nstroke = 0.4\ntime_ratio = 1.5\nframe = 0.3\nlamda = 3\n', "'lamda'"),
    "missing key": ('type = "slotted-link"\nstroke = 0.4\nframe = 0.3\n', "'time_ratio'"),
    "rod too short": ('type = "slotted-link"\nstroke = 0.4\ntime_ratio = 2.5\nframe = 0.3\nrod_ratio = 0.01\n',
                      "'rod_ratio'"),
    "bad load in the task": ('type = "crank-slider"\nstroke = 0.1\nlambda = 0.25\n[load]\non = "Z"\nforce = [1, 1]\n'
                             'stroke = [0, 1]\n', "load.on"),
}


@pytest.mark.parametrize("case", list(HOSTILE))
def test_hostile_tasks_one_line_exit_2_no_files(case, tmp_path):
    text, key = HOSTILE[case]
    task = tmp_path / "task.toml"
    task.write_text(text, encoding="utf-8")
    r = run("synth", task, "--out", tmp_path / "o", "--no-plots", "--lang", "en")
    assert_one_line_error(r, key)
    assert not (tmp_path / "o").exists()


def _linkage_numbers(name: str):
    c = cycle(parse_mechanism(tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))))
    return c.stroke, c.time_ratio


def test_synthesis_gives_back_the_examples_lengths_from_their_own_h_k_psi():
    """The examples of docs/examples were drawn by hand; tmm linkage's H, K, ψ of each, synthesised
    back, give their lengths (docs/synthesis.md's worked examples)."""
    from tmm_cli.linkage.synthesis import crank_slider_central, slotted_link

    h, k = _linkage_numbers("shaper.toml")  # O1O2 = 0.30, O1A = 0.10, O2B = 0.50, BC = 0.20
    s = slotted_link(h, k, 0.30, rod_ratio=0.4)
    assert (s.crank, s.link, s.rod) == pytest.approx((0.10, 0.50, 0.20), rel=1e-9)
    h, k = _linkage_numbers("compressor.toml")  # r = 0.06, l = 0.24
    s = crank_slider_central(h, 0.25)
    assert (s.crank, s.rod, k) == pytest.approx((0.06, 0.24, 1.0), rel=1e-9)
    psi, k = _linkage_numbers("four_bar.toml")  # OA = 0.08, AB = 0.28, BC = 0.20, OC = 0.30
    s = crank_rocker(0.20, psi, k, frame=0.30)
    assert (s.crank, s.coupler) == pytest.approx((0.08, 0.28), rel=1e-9)


# ---------------------------------------------------------------------------------------------------
# the note: «Синтез механизма» opens chapter 1 when the file records its task

def _note_of(text: str, lang: str = "ru"):
    return _note_of_figs(text, lang, None)


def _note_of_figs(text: str, lang: str, figures):
    from dataclasses import replace

    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.linkage.sheet2 import analyse_sheet2
    from tmm_cli.linkage.sheet2_file import parse_sheet2
    from tmm_cli.project import run_project
    from tmm_cli.render.note import build_note
    from tmm_cli.variants import get_variant

    m = parse_mechanism(tomllib.loads(text), "m.toml")
    r = replace(run_project(get_variant("17")), linkage=analyse_sheet2(analyse_mechanism(m), parse_sheet2(m)))
    return build_note(r, lang, figures)


def _synth_text(name: str) -> str:
    t = parse_task(tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8")))
    return synthesised_file(synthesise(t), t, default_name="M").text


@pytest.mark.parametrize("name,length_mm", [("synth_slider.toml", "97,24"), ("synth_rocker.toml", "169,75"),
                                             ("synth_shaper.toml", "647,214")])
def test_note_opens_chapter_1_with_the_synthesis(name, length_mm):
    from tmm_cli.render.note.mathsyntax import check_line
    from tmm_cli.render.note.model import Formula, Heading, all_math

    text = _synth_text(name)
    doc = _note_of(text)
    heads = [(b.level, b.text) for b in doc.blocks if isinstance(b, Heading)]
    i = next(k for k, h in enumerate(heads) if h[0] == 1 and "рычажного" in h[1])
    assert heads[i + 1] == (2, "Синтез механизма")
    assert {"kind": "linkage_synthesis", "type": tomllib.loads(text)["synthesis"]["type"], "matches": True} in doc.claims
    assert all(c.ok for _, src in all_math(doc) for c in check_line(src))
    formulas = " ".join(b.math for b in doc.blocks if isinstance(b, Formula))
    assert f'"{length_mm}"' in formulas  # a length the file holds (in mm), derived in the section


def test_note_says_when_the_lengths_were_changed_after_synthesis():
    from tmm_cli.render.note.model import Paragraph

    text = _synth_text("synth_slider.toml").replace("length = 0.0485", "length = 0.0490", 1)
    assert "length = 0.0490" in text
    doc = _note_of(text, "en")
    assert {"kind": "linkage_synthesis", "type": "crank-slider", "matches": False} in doc.claims
    assert any(isinstance(b, Paragraph) and "changed afterwards" in b.text for b in doc.blocks)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_an_edited_file_says_which_lengths_changed_and_gives_the_task(lang):
    """B8: no literal backticks; the lengths that differ from the synthesis, with both values; the
    task's data."""
    from tmm_cli.render.note.model import Heading, Paragraph

    text = _synth_text("synth_rocker.toml").replace("lengths = [0.1697", "lengths = [0.1797", 1)
    assert "lengths = [0.1797" in text
    doc = _note_of(text, lang)
    i = next(k for k, b in enumerate(doc.blocks) if isinstance(b, Heading) and b.text in ("Синтез механизма", "Synthesis of the mechanism"))
    para = doc.blocks[i + 1]
    assert isinstance(para, Paragraph) and "`" not in para.text
    assert "l_(B C) = " in para.text and ("169,75" if lang == "ru" else "169.75") in para.text
    assert "l_(A B)" not in para.text  # only what changed
    assert "l_(C D) = 200$" in para.text and 'γ_"min" >=' in para.text


def test_no_synthesis_section_without_the_record():
    from tmm_cli.render.note.model import Heading

    doc = _note_of((EXAMPLES / "four_bar.toml").read_text(encoding="utf-8"), "en")
    assert not any(isinstance(b, Heading) and b.text == "Synthesis of the mechanism" for b in doc.blocks)


# ---------------------------------------------------------------------------------------------------
# sheet 1 draws the construction

@pytest.mark.parametrize("name,angle", [("synth_slider.toml", "θ = 16,36°"), ("synth_rocker.toml", "θ = 16,36°"),
                                        ("synth_shaper.toml", "ψ = θ = 36,00°")])
def test_sheet1_draws_the_construction(name, angle, tmp_path):
    from test_sheets import TITLE, check_layout, reopen

    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    s = analyse_mechanism(parse_mechanism(tomllib.loads(_synth_text(name)), "m.toml"))
    doc = reopen(sheet1(s, "ru", TITLE), tmp_path, "sheet1")
    check_layout(doc)
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    assert angle in texts
    plain = analyse_mechanism(parse_mechanism({k: v for k, v in tomllib.loads(_synth_text(name)).items()
                                               if k != "synthesis"}, "m.toml"))
    (tmp_path / "plain").mkdir()
    doc2 = reopen(sheet1(plain, "ru", TITLE), tmp_path / "plain", "sheet1")
    assert angle not in [e.dxf.text for e in doc2.modelspace().query("TEXT")]


def test_rocker_note_derives_every_number_and_shows_the_construction():
    """B6: AC₁, AC₂ and l_AD come with formulas and substitutions (from the coordinates of the chosen
    pivot on the locus), γ_min with cos γ and its substitution; the given data name γ ≥ γ_task; the
    figure of the construction is embedded with a caption when drawn."""
    from tmm_cli.render.note.mathsyntax import check_line
    from tmm_cli.render.note.model import Figure, Formula, Heading, Paragraph

    from tmm_cli.render.note import note_figures

    text = _synth_text("synth_rocker.toml")
    doc = _note_of_figs(text, "ru", {"linkage_synthesis": ("a.svg", "a.png", 16.5, 13.0)})
    blocks = doc.blocks
    i = next(k for k, b in enumerate(blocks) if isinstance(b, Heading) and b.text == "Синтез механизма")
    j = next(k for k in range(i + 1, len(blocks)) if isinstance(blocks[k], Heading))
    section = blocks[i:j]
    math_ = [b.math for b in section if isinstance(b, Formula)]
    for lhs, result in (("A C_1 = sqrt", '"105,100"'), ("A C_2 = sqrt", '"234,408"'), ("l_(A D) = sqrt", '"211,11"'),
                        ("cos μ_1 =", '"0,6976"'), ("l_(A B) = (A C_2 - A C_1)/2", '"64,65"')):
        f = next(m for m in math_ if m.startswith(lhs))
        assert result in f and all(c.ok for c in check_line(f))
    words = " ".join(b.text for b in section if isinstance(b, Paragraph))
    assert 'γ_"min" >= "40°"' in words and '"45,77°"' in words
    figs = [b for b in section if isinstance(b, Figure)]
    assert [f.name for f in figs] == ["linkage_synthesis"] and figs[0].caption
    assert "{fig:linkage_synthesis}" in words
    m = parse_mechanism(tomllib.loads(text), "m.toml")
    from types import SimpleNamespace

    from tmm_cli.linkage.sheet1 import analyse_mechanism

    s1 = analyse_mechanism(m)
    assert note_figures(SimpleNamespace(linkage=SimpleNamespace(sheet1=s1)))[0] == "linkage_synthesis"
    plain = analyse_mechanism(parse_mechanism({k: v for k, v in tomllib.loads(text).items() if k != "synthesis"}))
    assert "linkage_synthesis" not in note_figures(SimpleNamespace(linkage=SimpleNamespace(sheet1=plain)))


def test_the_construction_figure_of_the_note_lies_on_the_mirrored_mechanism():
    """The rocker example is written mirrored (its load makes the other stroke the working one): the
    figure's C₁, C₂ and locus follow the drawn mechanism, not the unmirrored synthesis."""
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.figures.synth import recorded_construction_figure

    s1 = analyse_mechanism(parse_mechanism(tomllib.loads(_synth_text("synth_rocker.toml")), "m.toml"))
    fig = recorded_construction_figure(s1, "ru", (165.0, 130.0))
    ax = fig.axes[0]
    marks = {t.get_text(): t.xy for t in ax.texts if hasattr(t, "xy")}
    c = s1.cycle
    ends = [complex(c.kin.z["C"][p.index]) * 1000 for p in c.positions if p.extreme in ("start", "end")]
    for name in ("$C_1$", "$C_2$"):
        z = complex(*marks[name])
        assert min(abs(z - e) for e in ends) < 1e-6


@pytest.mark.parametrize("name,want", [
    ("synth_slider.toml", ["H = 100,0", "e = 20,0", "B1", "B2"]),
    ("synth_rocker.toml", ["ψ = 40,00°", "R = 242,8", "C1C2 = 136,8", "C1", "C2"]),
    ("synth_shaper.toml", ["f = 31,7"])])
def test_sheet1_labels_the_construction(name, want, tmp_path):
    """B7: the crank-rocker's C₁, C₂, the chord, ψ at D and the locus radius R (the locus an arc inside
    the field); the crank-slider's B₁, B₂, e and H; the shaper's f as a dimension of the sagitta
    (a dimension line of the sagitta's length between two arrowheads, not a leader to the arc)."""
    from test_sheets import TITLE, fields, reopen

    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    s = analyse_mechanism(parse_mechanism(tomllib.loads(_synth_text(name)), "m.toml"))
    doc = reopen(sheet1(s, "ru", TITLE), tmp_path, "sheet1")
    msp = doc.modelspace()
    texts = [e.dxf.text for e in msp.query("TEXT")] + [e.plain_text().replace("^", "") for e in msp.query("MTEXT")]
    for w in want:
        assert w in texts, (w, texts)
    box = fields(doc)["scheme"]["box"]
    x0, y0, x1, y1 = box
    for e in msp.query("LWPOLYLINE[layer=='Осевые']"):
        for x, y, *_ in e.get_points():
            assert x0 - 1e-6 <= x <= x1 + 1e-6 and y0 - 1e-6 <= y <= y1 + 1e-6
    assert not msp.query("CIRCLE[layer=='Осевые']") and not msp.query("ARC[layer=='Осевые']")
    if name == "synth_shaper.toml":
        scale = fields(doc)["scheme"]["scale"]
        f_sheet = 31.677 * scale
        dims = [e for e in msp.query("LINE[layer=='Размеры']")
                if abs(abs(e.dxf.end.y - e.dxf.start.y) - (f_sheet + 14.0)) < 0.2 and abs(e.dxf.end.x - e.dxf.start.x) < 0.5]
        assert dims, "no dimension line along the sagitta"


def test_russian_errors_and_warnings_use_decimal_commas_and_advise_what_the_file_takes(tmp_path):
    """B10: «0,3 м … 34,88°» in Russian; the low-γ warning of a task with a frame advises another
    frame (written as the file takes it, «frame = 0.2111») or no frame with min_transmission_deg —
    and that advice, followed, is accepted."""
    task = tmp_path / "e.toml"
    task.write_text('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 1.2\nframe = 0.3\n'
                    'min_transmission_deg = 40\n', encoding="utf-8")
    r = run("synth", task, "--out", tmp_path / "o", "--no-plots", "--lang", "ru")
    assert r.exit_code == 2 and len(r.stderr.strip().splitlines()) == 1 and r.stderr.startswith("tmm: ошибка:")
    assert "'min_transmission_deg'" in r.stderr and "0,3 м" in r.stderr and "34,88°" in r.stderr and "0.3" not in r.stderr
    task.write_text('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 1.2\nframe = 0.3\n',
                    encoding="utf-8")
    r = run("synth", task, "--out", tmp_path / "o", "--no-plots", "--json", "--lang", "ru")
    assert r.exit_code == 0, r.output
    warning = next(n for n in json.loads(r.stdout)["notes"] if "34,9°" in n)
    assert "frame = 0.2111" in warning and "min_transmission_deg = 40" in warning and "34.9" not in warning
    for fix in ('frame = 0.2111\n', 'min_transmission_deg = 40\n'):
        task.write_text('type = "crank-rocker"\nrocker = 0.2\nswing_deg = 40\ntime_ratio = 1.2\n' + fix, encoding="utf-8")
        r = run("synth", task, "--out", tmp_path / "o", "--no-plots", "--json", "--lang", "en", "--force")
        assert r.exit_code == 0, r.output
        assert json.loads(r.stdout)["checks"]["gamma_min_deg"]["linkage"] >= 40.0


def test_note_titles_words_and_one_rounding_per_number():
    """C11: «ход» for a slider, «размах» for a rocker; C12: ψ = θ and f as formulas, one number per
    formula, a number printed with one rounding wherever it appears, the rod ratio said given or
    assumed («принято»); C14: chapter 1's title names the synthesis (not when edited)."""
    import re

    from tmm_cli.render.note.model import Formula, Heading, Paragraph

    def section(doc):
        blocks = doc.blocks
        i = next(k for k, b in enumerate(blocks) if isinstance(b, Heading) and b.text == "Синтез механизма")
        assert blocks[i - 1].level == 1 and blocks[i - 1].text.startswith("Синтез, структурный и кинематический анализ")
        j = next(k for k in range(i + 1, len(blocks)) if isinstance(blocks[k], Heading))
        return blocks[i:j]

    last = {n: [b.text for b in section(_note_of(_synth_text(n))) if isinstance(b, Paragraph)][-1]
            for n in ("synth_slider.toml", "synth_rocker.toml")}
    assert "ход" in last["synth_slider.toml"] and "размах" not in last["synth_slider.toml"]
    assert "размах" in last["synth_rocker.toml"] and "(или" not in last["synth_rocker.toml"]
    sec = section(_note_of(_synth_text("synth_shaper.toml")))
    maths = [b.math for b in sec if isinstance(b, Formula)]
    assert any(m.startswith("ψ = θ = ") for m in maths) and any(m.startswith("f = l_(O_2 B)") for m in maths)
    assert all(" quad " not in m and m.count(" thin ") <= 1 for m in maths)  # one number per formula
    numbers = re.findall(r'"(\d+,\d+)"', " ".join(maths))
    for a in numbers:  # no number printed both rounded and unrounded (647,21 beside 647,214)
        assert not any(b != a and b.startswith(a) and float(a.replace(",", ".")) > 100 for b in numbers), a
    words = " ".join(b.text for b in sec if isinstance(b, Paragraph))
    assert "k = " in words and "обычно" in words
    text = _synth_text("synth_shaper.toml").replace("rod_ratio = 0.3\n", "")
    words = " ".join(b.text for b in section(_note_of(text)) if isinstance(b, Paragraph))
    assert "принято" in words
    edited = _synth_text("synth_slider.toml").replace("length = 0.0485", "length = 0.0490", 1)
    heads = [b.text for b in _note_of(edited).blocks if isinstance(b, Heading) and b.level == 1]
    assert "Структурный и кинематический анализ рычажного механизма" in heads


def test_sheet1_title_names_the_synthesis(tmp_path):
    """C14: sheet 1's name in the title block."""
    from test_sheets import TITLE, reopen

    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    s = analyse_mechanism(parse_mechanism(tomllib.loads(_synth_text("synth_slider.toml")), "m.toml"))
    doc = reopen(sheet1(s, "ru", TITLE), tmp_path, "sheet1")
    texts = " ".join(e.dxf.text for e in doc.modelspace().query("TEXT")) + " ".join(
        e.plain_text() for e in doc.modelspace().query("MTEXT"))
    assert "Синтез и кинематический анализ" in texts


def test_a_poor_crank_slider_is_warned_of_and_a_good_one_is_not(tmp_path):
    """C18: a pressure angle near or above 45° (λ near 0,5) is legal but poor: a visible warning."""
    poor = analysed_notes({"type": "crank-slider", "stroke": 0.10, "time_ratio": 1.2, "offset": 0.02})
    assert [n.code for n in poor if n.code == "synth_slider_pressure"] == ["synth_slider_pressure"]
    assert poor[[n.code for n in poor].index("synth_slider_pressure")].level == "warning"
    good = analysed_notes({"type": "crank-slider", "stroke": 0.12, "lambda": 0.25})
    assert "synth_slider_pressure" not in [n.code for n in good]
    task = tmp_path / "t.toml"
    task.write_text('type = "crank-slider"\nstroke = 0.1\nlambda = 0.45\n', encoding="utf-8")
    r = run("synth", task, "--out", tmp_path / "o", "--no-plots", "--lang", "ru")
    assert r.exit_code == 0 and "давления" in r.output and "0,450" in r.output


def analysed_notes(task: dict):
    t = parse_task(task)
    return synthesised_file(synthesise(t), t).notes


def test_the_terminal_derives_the_rocker_pivot_too(tmp_path):
    """B6 in the terminal: AC₁, AC₂, l_AD and the angles μ with their formulas and substitutions."""
    r = run("synth", EXAMPLES / "synth_rocker.toml", "--out", tmp_path, "--no-plots", "--lang", "ru")
    assert r.exit_code == 0, r.output
    out = " ".join(r.stdout.split())
    assert "AC₁ = √((x_A − x_C₁)² + (y_A − y_C)²) = √((160,447" in out and "= 105,100 мм" in out
    assert "l_AD = √(x_A² + y_A²) = √(160,447² + 137,205²) = 211,11 мм" in out
    assert "μ₁ = 45,77°" in out and "R = C₁C₂/(2·sin θ) = 136,808/" in out


def test_the_sheets_font_draws_theta_as_the_note_does():
    """C13: the sheets' osifont drew «θ» in the script form «ϑ» (the note prints θ); tmm's copy draws
    θ as a closed oval with its bar — «Θ» narrowed — and keeps ϑ as its own glyph."""
    from fontTools.pens.recordingPen import DecomposingRecordingPen
    from fontTools.ttLib import TTFont

    font = TTFont(Path(__file__).resolve().parents[1] / "tmm_cli" / "render" / "sheets" / "fonts" / "osifont.ttf")
    cmap, gs = font.getBestCmap(), font.getGlyphSet()

    def contours(cp):
        pen = DecomposingRecordingPen(gs)
        gs[cmap[cp]].draw(pen)
        return [op for op, _ in pen.value if op in ("closePath", "endPath")], pen.value

    theta, big, script = contours(0x03B8), contours(0x0398), contours(0x03D1)
    assert len(theta[0]) == len(big[0]) and theta[1] != script[1]
    assert font["hmtx"][cmap[0x03B8]][0] < font["hmtx"][cmap[0x0398]][0]
