"""Sheet-4 figures checked for what a reader sees: labels that do not cover one another, the
line of action and the rotation arrows matching the senses of rotation, the 2β arc visible."""

import itertools
import math

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.patches import Arc

from tmm_cli.gears.design import design_gears
from tmm_cli.render.figures.gears import _mesh_geometry, gears_figures

# the three reducers of the review (variant 17 has n_k = −1000 rpm) and one cam turning ccw
CASES = {
    "s1": dict(n_cam_rpm=-1000, crank_rpm=220, ratio=(13, 4)),
    "s2": dict(n_cam_rpm=-1000, crank_rpm=67, ratio=(53, 5)),
    "s11": dict(n_cam_rpm=-1000, crank_rpm=40),
    "s11_30": dict(n_cam_rpm=-1000, crank_rpm=30),  # "H1 = k2" fell on the arrow V_A1 and its label
    "ccw_cam": dict(n_cam_rpm=800, crank_rpm=220),
}


@pytest.fixture(scope="module")
def drawn():
    out = {}
    for key, kw in CASES.items():
        r = design_gears(**kw)
        for lang in ("en", "ru"):
            figs = gears_figures(r, lang)
            for f in figs.values():
                FigureCanvasAgg(f)
                f.canvas.draw()
            out[key, lang] = (r, figs)
    return out


def _shown_texts(ax, renderer):
    """Texts and annotations actually drawn (an annotation whose point is outside is not)."""
    out = []
    for t in ax.texts:
        if not t.get_visible() or not t.get_text().strip():
            continue
        if hasattr(t, "_check_xy") and not t._check_xy(renderer):
            continue
        out.append(t)
    return out


@pytest.mark.parametrize("key", list(CASES))
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_labels_do_not_overlap(drawn, key, lang):
    _, figs = drawn[key, lang]
    bad = []
    for name, f in figs.items():
        rend = f.canvas.get_renderer()
        for ax in f.axes:
            boxes = [(t.get_text(), t.get_window_extent(rend)) for t in _shown_texts(ax, rend)]
            for (a, ba), (b, bb) in itertools.combinations(boxes, 2):
                if ba.overlaps(bb):
                    bad.append((name, a, b))
    assert not bad


@pytest.mark.parametrize("key", list(CASES))
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_label_stays_inside_its_axes(drawn, key, lang):
    """No label leaves the picture it belongs to (the Russian caption of the angular-velocity picture
    ran from the pole to the very edge of the figure)."""
    _, figs = drawn[key, lang]
    bad = []
    for name, f in figs.items():
        rend = f.canvas.get_renderer()
        for ax in f.axes:
            frame = ax.get_window_extent(rend).padded(1)
            for t in _shown_texts(ax, rend):
                box = t.get_window_extent(rend)
                if not (frame.contains(box.x0, box.y0) and frame.contains(box.x1, box.y1)):
                    bad.append((name, t.get_text()))
    assert not bad


def _annotation(ax, text):
    hits = [t for t in ax.texts if t.get_text() == text]
    assert len(hits) == 1, text
    return np.asarray(hits[0].xy, dtype=float)


@pytest.mark.parametrize("key", ["s1", "ccw_cam"])
def test_line_of_action_follows_the_motor(drawn, key):
    r, figs = drawn[key, "en"]
    g = r.spur
    motor = r.directions.motor
    assert motor == ("ccw" if r.cam_rpm < 0 else "cw")  # the external pair reverses the cam's sense
    o1, o2, p, u, n1, at = _mesh_geometry(g, motor)
    # gear 1 drives: its pitch-point velocity ω × O1P has a positive component along N1 → N2
    w = 1.0 if motor == "ccw" else -1.0
    v_p = w * np.array([-(p - o1)[1], (p - o1)[0]])
    assert float(v_p @ u) > 0
    # N1 (on gear 1's base circle) and N2 as drawn in the zoomed mesh
    ax = figs["gears_mesh"].axes[1]
    x_n1 = _annotation(ax, "$N_1$")[0]
    x_n2 = _annotation(ax, "$N_2$")[0]
    assert (x_n1 < x_n2) == (motor == "cw")
    assert np.allclose(_annotation(ax, "$N_1$"), n1)
    # P1 (gear 2's tip circle) is on N1's side of the pole, P2 on N2's
    assert (_annotation(ax, "$P_1$")[0] - p[0]) * (x_n1 - p[0]) > 0


@pytest.mark.parametrize("key", ["s1", "ccw_cam"])
def test_rotation_arrows_show_both_senses(drawn, key):
    r, figs = drawn[key, "en"]
    ax = figs["gears_mesh"].axes[0]
    texts = [t.get_text() for t in ax.texts]
    assert "ω1" in texts and "ω2" in texts
    title = ax.get_title()
    sense = {"cw": "clockwise", "ccw": "counter-clockwise"}
    assert f"motor ({sense[r.directions.motor]})" in title and f"cam ({sense[r.directions.cam]})" in title
    assert r.directions.motor != r.directions.cam


@pytest.mark.parametrize("key", ["s1", "s2", "s11"])
def test_assembly_angle_label_leaves_the_arc_visible(drawn, key):
    r, figs = drawn[key, "en"]
    f = figs["gears_assembly"]
    rend = f.canvas.get_renderer()
    for ax, st in zip(f.axes, r.planetary.stages):
        arcs = [p for p in ax.patches if isinstance(p, Arc) and p.center == (0, 0)]
        assert len(arcs) == 1
        arc = arcs[0]
        k = st.planets
        rad = arc.width / 2
        mid = math.radians(90 + 180 / k)
        mid_px = ax.transData.transform((rad * math.cos(mid), rad * math.sin(mid)))
        label = [t for t in ax.texts if t.get_text().startswith("2β")][0]
        assert not label.get_window_extent(rend).contains(*mid_px)
