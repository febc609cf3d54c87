"""The profile drawing scale (§1.4, Table 1.1) and the sizes (1.26)–(1.27), all 68 variants,
plus the true-to-scale figure "cam_profile_scaled"."""

import io
import math
import re

import numpy as np
import pytest

from tmm_cli.cam.design import design_cam

# Table 1.1, typed from the book: M and k_Sk [m/mm]
TABLE_1_1 = {"1:10": 0.01, "1:5": 0.005, "1:2": 0.002, "1:1": 0.001, "2:1": 0.0005, "5:1": 0.0002, "10:1": 0.0001}
FIELD_MM = 250.0


@pytest.fixture(scope="module")
def results(table):
    return {n: design_cam(v) for n, v in table.items()}


def _extent_m(r) -> float:
    """Independent: the pitch curve dilated by the roller bounds every roller and both envelopes."""
    p = r.profile
    rp = p.roller_m
    x, y = p.pitch[:, 0], p.pitch[:, 1]
    w = (x.max() + rp) - (x.min() - rp)
    h = (y.max() + rp) - (y.min() - rp)
    for env in (p.inner, p.outer):
        if env is not None:  # the envelopes lie inside that box
            assert env[:, 0].min() >= x.min() - rp - 1e-9 and env[:, 0].max() <= x.max() + rp + 1e-9
            assert env[:, 1].min() >= y.min() - rp - 1e-9 and env[:, 1].max() <= y.max() + rp + 1e-9
    return max(w, h)


def _construction_extent_m(r) -> float:
    """Independent: the cam's box, and for a rocker the circle |x| = l_OC about O on which the
    pivot positions C_i of the inversion lie (sheet 3 draws it)."""
    p = r.profile
    rp = p.roller_m
    x0, x1 = p.pitch[:, 0].min() - rp, p.pitch[:, 0].max() + rp
    y0, y1 = p.pitch[:, 1].min() - rp, p.pitch[:, 1].max() + rp
    if r.sizing.l_oc_m is not None:
        L = r.sizing.l_oc_m
        x0, x1, y0, y1 = min(x0, -L), max(x1, L), min(y0, -L), max(y1, L)
    return max(x1 - x0, y1 - y0)


def test_scale_is_standard_fits_and_is_the_largest(results):
    seen = set()
    order = list(TABLE_1_1)  # coarse to detailed
    for n, r in results.items():
        d = r.drawing
        assert d.scale in TABLE_1_1, n
        assert d.k_sk == TABLE_1_1[d.scale], n
        assert d.field_mm == FIELD_MM
        assert d.extent_m == pytest.approx(_extent_m(r), rel=1e-12, abs=1e-12), n
        ext = _construction_extent_m(r)
        assert d.construction_extent_m == pytest.approx(ext, rel=1e-12, abs=1e-12), n
        assert d.fits
        assert ext / d.k_sk <= FIELD_MM, n  # fits the field at the chosen scale
        i = order.index(d.scale)
        if i + 1 < len(order):  # and would not fit at the next larger one
            assert ext / TABLE_1_1[order[i + 1]] > FIELD_MM, n
        w, h = d.extent_mm
        assert max(w, h) == pytest.approx(_extent_m(r) / d.k_sk, rel=1e-12)
        seen.add(d.scale)
    assert {"1:2", "1:1", "2:1"} <= seen  # the table spreads the variants over several scales


def test_sizes_1_26_1_27_are_si_over_k_sk(results, table):
    for n, r in results.items():
        v, d, z, p, sc = table[n], r.drawing, r.sizing, r.profile, r.motion.scales
        k_s = sc.k_s_b if v.is_rocker else sc.k_s
        assert d.k_s == k_s and d.k_s_prime == k_s  # k_S' = k_S (stated)
        want = {"r0": z.r0_m, "roller": p.roller_m, "working_min_radius": z.r0_m - p.roller_m, "far_dwell_radius": p.r_far_m}
        if v.is_rocker:
            want |= {"l_oc": z.l_oc_m, "l_bc": v.l_bc_m, "stroke": math.radians(v.stroke) * v.l_bc_m}
        else:
            want |= {"e": z.e_m, "stroke": v.stroke}
        assert {s.name for s in d.sizes} == set(want), n
        for s in d.sizes:
            assert s.length_m == pytest.approx(want[s.name], rel=1e-12, abs=1e-15), (n, s.name)
            assert s.at_k_s_mm == pytest.approx(want[s.name] / k_s, rel=1e-12, abs=1e-12)  # x_i, y_Si
            # (1.26)/(1.27): (k_S/k_Sk)·y_Si = l/k_Sk
            assert s.drawn_mm == pytest.approx((k_s / d.k_sk) * s.at_k_s_mm, rel=1e-12, abs=1e-12)
            assert s.drawn_mm == pytest.approx(want[s.name] / d.k_sk, rel=1e-12, abs=1e-12), (n, s.name)
            assert s.formula == ("1.26" if s.name == "stroke" else "1.27")
        assert d.size("stroke").at_k_s_mm == pytest.approx(sc.y_s_max_mm)  # y_Smax of the diagram
        # the displacements at the table positions: B_i B'_i = y_Sik
        rows = r.motion.table
        assert len(d.positions) == len(rows)
        for q, row in zip(d.positions, rows):
            s_si = row.s_b_m if v.is_rocker else row.s
            assert q.y_sk_mm == pytest.approx(s_si / d.k_sk, rel=1e-12, abs=1e-12)
            assert q.y_s_mm == pytest.approx(s_si / k_s, rel=1e-12, abs=1e-12)
            if v.is_rocker:  # the chord is at most the arc
                assert q.chord_mm == pytest.approx(2 * v.l_bc_m * math.sin(row.s / 2) / d.k_sk, rel=1e-12, abs=1e-12)
                assert q.chord_mm <= q.y_sk_mm + 1e-9
            else:
                assert q.chord_mm is None
        assert max(q.y_sk_mm for q in d.positions) == pytest.approx(d.size("stroke").drawn_mm)


def test_note_json_and_table(results):
    from rich.console import Console

    from tmm_cli.render.data.cam import cam_to_json
    from tmm_cli.render.terminal.cam import print_cam
    from tmm_cli.i18n.lang import note_text

    for n in (1, 4, 13, 54):
        r = results[n]
        d = r.drawing
        note = next(x for x in r.notes if x.code == "cam_drawing_scale")
        assert note.level == "assumption" and d.scale in note_text(note, "en") and "250" in note_text(note, "ru")
        j = cam_to_json(r, "en")["drawing"]
        assert j["scale"] == d.scale and j["k_sk_m_per_mm"] == d.k_sk and j["field_mm"] == FIELD_MM
        assert j["sizes_mm"]["r0"] == pytest.approx(r.sizing.r0_m / d.k_sk, abs=1e-3)
        assert j["sizes_mm"]["roller"] == pytest.approx(r.profile.roller_m / d.k_sk, abs=1e-3)
        assert ("l_oc" in j["sizes_mm"]) == r.variant.is_rocker and ("e" in j["sizes_mm"]) != r.variant.is_rocker
        for lang, title in (("en", "Profile drawing scale (Table 1.1)"), ("ru", "Масштаб построения профиля (табл. 1.1)")):
            con = Console(record=True, width=110, file=io.StringIO())
            print_cam(con, r, lang)
            out = con.export_text()
            assert title in out and d.scale in out


def _mediabox_pt(pdf: bytes) -> tuple[float, float]:
    m = re.findall(rb"/MediaBox\s*\[\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)\s*\]", pdf)
    assert len(m) == 1
    x0, y0, x1, y1 = (float(t) for t in m[0])
    return x1 - x0, y1 - y0


@pytest.mark.parametrize("n", [1, 2, 4, 13, 43, 54])  # all four schemes; scales 1:5, 1:2, 1:1, 2:1
def test_scaled_figure_is_true_to_scale(results, n, tmp_path):
    from tmm_cli.render.figures.cam import cam_figures, scaled_layout
    from tmm_cli.render.figures.save import save_figures

    r = results[n]
    d = r.drawing
    fig = cam_figures(r, "en" if n % 2 else "ru")["cam_profile_scaled"]
    assert str(n) in fig.get_suptitle() and d.scale in fig.get_suptitle()
    assert fig.get_layout_engine() is None
    w_mm, h_mm = (x * 25.4 for x in fig.get_size_inches())
    lay = scaled_layout(r)
    assert (w_mm, h_mm) == pytest.approx(lay["paper_mm"], rel=1e-12)
    # the page holds the cam at k_Sk plus the margins (no more than 40 mm each way)
    w_draw, h_draw = d.extent_mm
    assert w_draw < w_mm <= max(w_draw + 40.0, 120.0) and h_draw < h_mm <= h_draw + 40.0
    fig.canvas.draw()
    ax = fig.axes[0]
    assert ax.get_position().bounds == pytest.approx((0.0, 0.0, 1.0, 1.0), abs=1e-12)
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    # 1 mm of paper is k_Sk metres of the cam (axes in real mm), on both axes
    assert (x1 - x0) / w_mm == pytest.approx(d.k_sk * 1000.0, rel=1e-12)
    assert (y1 - y0) / h_mm == pytest.approx(d.k_sk * 1000.0, rel=1e-12)
    bx0, bx1, by0, by1 = (c * 1000.0 for c in d.bbox_m)
    assert x0 < bx0 and bx1 < x1 and y0 < by0 and by1 < y1  # the whole cam is on the page
    # the check bar: a horizontal line 50 mm long on paper
    bars = [ln for ln in ax.get_lines() if len(ln.get_xdata()) == 2 and ln.get_ydata()[0] == ln.get_ydata()[1]
            and (ln.get_xdata()[1] - ln.get_xdata()[0]) / (d.k_sk * 1000.0) == pytest.approx(50.0, rel=1e-12)]
    assert bars
    assert any(t.get_text() == f"M {d.scale}" or t.get_text() == f"М {d.scale}" for t in ax.texts)
    # the saved PDF page (save_figures, as the project does): MediaBox in points = paper mm / 25.4 · 72
    (path,) = save_figures(tmp_path, {"cam_profile_scaled": fig}, "pdf")
    pw, ph = _mediabox_pt(path.read_bytes())
    assert pw == pytest.approx(w_mm / 25.4 * 72.0, abs=1e-3) and ph == pytest.approx(h_mm / 25.4 * 72.0, abs=1e-3)
    # and the SVG declares the same physical size
    (svg,) = save_figures(tmp_path, {"cam_profile_scaled": fig}, "svg")
    head = svg.read_text()[:2000]
    sw, sh = (float(x) for x in re.search(r'width="([\d.]+)pt" height="([\d.]+)pt"', head).groups())
    assert sw == pytest.approx(w_mm / 25.4 * 72.0, abs=1e-3) and sh == pytest.approx(h_mm / 25.4 * 72.0, abs=1e-3)


def test_choose_scale_edges():
    from tmm_cli.cam.drawing import STANDARD_SCALES, choose_scale, next_larger_scale

    assert dict(STANDARD_SCALES) == TABLE_1_1
    assert choose_scale(0.250) == ("1:1", 0.001, True)  # exactly the field
    assert choose_scale(0.2501) == ("1:2", 0.002, True)
    assert choose_scale(0.001) == ("10:1", 0.0001, True)
    # larger than 2.5 m: flagged, not raised, at the next reduction of ГОСТ 2.302 that fits
    assert choose_scale(3.0) == ("1:15", 0.015, False)
    assert choose_scale(4.9) == ("1:20", 0.02, False)
    assert choose_scale(100.0)[0] == "1:100" and not choose_scale(100.0)[2]
    assert next_larger_scale(0.0001) is None
    assert np.isclose(next_larger_scale(0.01)[1], 0.005)
