"""The planetary reducer's module of the drawing in the note's figures (issue 32): the figures said
«μl = 1 мм/мм (m = 1 мм)» while sheet 4 draws the reducer with a chosen module. Now Figures 5 and 6
state sheet 4's module — the one its scheme's and assembly's captions print (read from the DXF) — and
scales that hold at it, measured on the figure: μ_l from a drawn radius, μ_V from the drawn V_A.
A few designs (one- and two-stage reducers) here; every design of the 68 variants with -m slow."""

from __future__ import annotations

import math
import re

import pytest

from tmm_cli.gears.design import design_gears
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.variants import load_table

V = load_table()
MM = 25.4


def _designs():
    seen, out = set(), []
    for n in sorted(V):
        if V[n].n_cam_rpm not in seen:
            seen.add(V[n].n_cam_rpm)
            out.append((n, None))
    return out


ALL = _designs()
FEW = [(52, None), (17, None), (8, None), (1, 40.0), (33, 960.0)]  # crank 40 and 960 rpm: two-stage reducers
REST = [d for d in ALL if d not in FEW]


def _num(text: str) -> float:
    return float(text.replace(",", ".").replace("\u2009", "").replace(" ", ""))


def _sheet_modules(g, n) -> list[float]:
    """The module(s) sheet 4 prints for the reducer: its scheme's caption (after k_l) and its assembly's."""
    from tmm_cli.render.sheets import sheet4

    sh = sheet4(g, n, "ru", TitleFields())
    texts = [e.dxf.text if e.dxftype() == "TEXT" else e.text for e in sh.doc.modelspace().query("TEXT MTEXT")]
    found = [_num(m[1]) for t in texts if ("kl =" in t or t.startswith("М ")) for m in re.finditer(r"m = ([\d,]+) мм", t)]
    assert len(found) == 2, texts
    return found


def _axes_mm(fig, ax):
    w, h = fig.get_size_inches() * MM
    p = ax.get_position()
    return p.width * w, p.height * h


def _check(n, crank):
    from tmm_cli.render.figures.note import note_figure_of, note_style

    g = design_gears(V[n].n_cam_rpm, crank, stiffness=False)
    m_sheet = _sheet_modules(g, n)
    assert m_sheet[0] == m_sheet[1]
    with note_style():
        fig = note_figure_of("gears_planetary", g, "ru")
        texts = {ax: [t.get_text() for t in ax.texts] for ax in fig.axes}
        ax_s, ax_v = fig.axes[0], fig.axes[1]
        mu_l_text = next(t for t in texts[ax_s] if "μ" in t)
        m = re.search(r"μ_\\text\{l\}\$ = ([\d,]+) м/мм \(m = ([\d,]+) мм\)", mu_l_text)
        assert m, mu_l_text
        mu_l, m_fig = _num(m[1]), _num(m[2])
        assert m_fig == m_sheet[0]  # the module sheet 4 prints
        # μ_l as drawn: the scheme's radii are in modules; modules per figure mm × m = mm per mm
        lo, hi = ax_s.get_ylim()
        mod_per_mm = (hi - lo) / _axes_mm(fig, ax_s)[1]
        assert math.isclose(mod_per_mm * m_fig / 1000, mu_l, rel_tol=1e-9), (mod_per_mm, m_fig, mu_l)
        # μ_V as drawn: V_A = ω_д r_k (r_k = z_k/2 modules) over the drawn length of its arrow
        mu_v_text = next(t for t in texts[ax_v] if "μ" in t)
        mv = re.search(r"= ([\d,]+) \(м/с\)/мм", mu_v_text)
        s0 = g.checks.velocity.stages[0]
        drawn_mm = s0.v_a / ((ax_v.get_xlim()[1] - ax_v.get_xlim()[0]) / _axes_mm(fig, ax_v)[0])
        v_real = math.pi * g.motor_rpm / 30 * g.planetary.stages[0].z_sun / 2 * m_fig / 1000
        assert math.isclose(v_real / drawn_mm, _num(mv[1]), rel_tol=6e-3), (v_real / drawn_mm, mv[1])
        fig.clf()
        fig = note_figure_of("gears_assembly", g, "ru")
        mu = [t.get_text() for ax in fig.axes for t in ax.texts if "μ" in t.get_text()]
        assert len(mu) == 1 and f"(m = {m_sheet[0]:g} мм)".replace(".", ",") in mu[0], mu
        assert "m = 1 мм" not in mu[0] or m_sheet[0] == 1
        fig.clf()


@pytest.mark.parametrize("n,crank", FEW)
def test_the_notes_reducer_figures_state_sheet_4s_module(n, crank):
    _check(n, crank)


@pytest.mark.slow
@pytest.mark.parametrize("n,crank", REST)
def test_the_notes_reducer_figures_state_sheet_4s_module_on_every_design(n, crank):
    _check(n, crank)
