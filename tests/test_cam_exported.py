"""Sheet 3 checked from the exported JSON alone, for all 68 variants.

Nothing from tmm_cli.cam (nor the variant table) is used here except to produce the JSON: the mechanism is rebuilt from
`pitch_curve_mm` (cam frame, cam centre at the origin, points every `pitch_curve_step_deg` of cam
angle from the start of the rise) and `follower_in_curve_frame` (the follower at φ = 0). The
motion is inverted by hand: at cam angle φ the cam has turned by φ in the sense of `rotation`, so
the roller centre in the fixed frame is B(φ) = R(±φ)·P(φ). From B(φ) the follower displacement is
recovered and compared with the motion law (closed forms written here); the pressure angle is
the angle between the normal to the pitch curve (local polynomial fits to the exported points
inside each smooth stretch, turned into the fixed frame) and the roller centre's velocity line (the axis, or ⟂ CB).

A mirrored curve or a wrong rotation sense for clockwise cams puts B(φ) off the follower's axis
(or off the rocker's circle) and fails here.
"""

import functools
import math

import numpy as np
import pytest

from tmm_cli.cam.design import design_cam
from tmm_cli.render.data.cam import cam_to_json
from reference_laws import law_f

PRESSURE_TOL_DEG = 0.05  # tangents fitted to points rounded to 1e-4 mm
FIT_POINTS = 17  # local quartic fit over 17 grid points (4° of cam angle)
CURVATURE_FIT_POINTS = 33  # 8°: the second derivative needs more smoothing
RHO_TOL = 0.03  # relative; the smallest radius often sits at a phase end, where the fit is one-sided


def fraction(d, phi_deg):
    """s/h at cam angle φ [deg] from the exported phases and law number."""
    ph = d["phases_deg"]
    r, f, b = ph["rise"], ph["far_dwell"], ph["return"]
    p = np.asarray(phi_deg, dtype=float)
    return np.where(
        p <= r,
        law_f(d["law"], p / r),
        np.where(p <= r + f, 1.0, np.where(p <= r + f + b, 1.0 - law_f(d["law"], (p - r - f) / b), 0.0)),
    )


def rotate(pts, ang):
    c, s = np.cos(ang), np.sin(ang)
    return np.stack([c * pts[:, 0] - s * pts[:, 1], s * pts[:, 0] + c * pts[:, 1]], axis=-1)


def inverted(d):
    """(φ [deg], P in the cam frame, B in the fixed frame, sense) from the JSON, closing point dropped."""
    pts = np.array(d["pitch_curve_mm"], dtype=float)
    step = d["pitch_curve_step_deg"]
    n = len(pts) - 1
    assert n * step == pytest.approx(360.0)
    phi = np.arange(n + 1) * step
    sense = 1.0 if d["rotation"] == "ccw" else -1.0
    b = rotate(pts, sense * np.radians(phi))
    return phi, pts, b, sense


def smooth_pieces(d):
    """Grid-index ranges (inclusive) of the rise and the return, each split where the pitch curve's
    curvature jumps (law 1: mid-phase, where the acceleration changes sign)."""
    step = d["pitch_curve_step_deg"]
    ph = d["phases_deg"]
    out = {}
    for phase, a0, length in (("rise", 0.0, ph["rise"]), ("return", ph["rise"] + ph["far_dwell"], ph["return"])):
        ends = [a0, a0 + length / 2, a0 + length] if d["law"] == 1 else [a0, a0 + length]
        idx = [round(a / step) for a in ends]
        out[phase] = list(zip(idx[:-1], idx[1:]))
    return out


@functools.lru_cache(maxsize=None)
def _fit_rows(m, deg, at):
    """Rows giving the first and second derivative at x = `at` of the least-squares polynomial of
    degree `deg` through m equally spaced samples x = 0 … m − 1."""
    x = np.arange(m, dtype=float) - at
    pinv = np.linalg.pinv(np.vander(x, deg + 1))  # coefficients of x^deg … x, 1
    return pinv[-2], 2.0 * pinv[-3]


def local_fit(pts, i0, i1, points, deg=4):
    """dP/dφ and d²P/dφ² (per grid step) at points i0..i1 by a local polynomial fit over `points`
    samples that stay inside [i0, i1]. The pitch curve's curvature jumps at the phase ends
    (laws 1–3) and at law 1's mid-phase, so a stencil straddling such a point would tilt the
    tangent; the fit also smooths the 1e-4 mm rounding of the exported points."""
    m = min(points, i1 - i0 + 1)
    deg = min(deg, m - 1)
    d1 = np.empty((i1 - i0 + 1, 2))
    d2 = np.empty((i1 - i0 + 1, 2))
    for i in range(i0, i1 + 1):
        lo = min(max(i - m // 2, i0), i1 - m + 1)
        r1, r2 = _fit_rows(m, deg, i - lo)
        win = pts[lo : lo + m]
        d1[i - i0], d2[i - i0] = r1 @ win, r2 @ win
    return d1, d2


def tangents(pts, i0, i1):
    """dP/dφ at points i0..i1 (local quartic over FIT_POINTS samples)."""
    return local_fit(pts, i0, i1, FIT_POINTS)[0]


def pressure_angles(d, phi, b, sense, tang_cam, idx):
    """ν [deg] at grid points idx: the angle between the pitch-curve normal and the velocity line
    of the roller centre, both in the fixed frame."""
    tang = rotate(tang_cam, sense * np.radians(phi[idx]))  # the cam-frame tangent, turned back
    g = d["follower_in_curve_frame"]
    if d["follower"] == "translating":
        u = np.broadcast_to(np.array(g["rise_direction"], dtype=float), tang.shape)
    else:
        cb = b[idx] - np.array(g["pivot_mm"])
        u = np.stack([-cb[:, 1], cb[:, 0]], axis=-1)  # velocity line of B: ⟂ CB
    u = u / np.hypot(u[:, 0], u[:, 1])[:, None]
    # angle between the normal and u = 90° − angle between the tangent and u
    cos_nu = np.abs(tang[:, 0] * u[:, 1] - tang[:, 1] * u[:, 0]) / np.hypot(tang[:, 0], tang[:, 1])
    return np.degrees(np.arccos(np.clip(cos_nu, 0.0, 1.0)))


@pytest.fixture(scope="module")
def exported(table):
    return {n: cam_to_json(design_cam(v), "en") for n, v in table.items()}


def test_json_carries_the_follower_geometry(exported):
    for n, d in exported.items():
        g = d["follower_in_curve_frame"]
        assert g["b0_mm"] == d["pitch_curve_mm"][0]
        assert g["rise_direction"] == [0.0, 1.0]
        rows = d["motion"]["table"]
        if d["follower"] == "rocker":
            assert d["s_max_mm"] is None and max(r["gamma_deg"] for r in rows) == pytest.approx(d["gamma_max_deg"])
        else:
            assert d["gamma_max_deg"] is None and 1000 * max(r["s_m"] for r in rows) == pytest.approx(d["s_max_mm"])
        if d["follower"] == "rocker":
            assert g["axis_point_mm"] is None
            assert math.hypot(*g["pivot_mm"]) == pytest.approx(d["l_oc_mm"], abs=2e-4)
            assert math.dist(g["pivot_mm"], g["b0_mm"]) == pytest.approx(d["l_bc_mm"], abs=2e-4)
            assert g["rocker_turns_on_rise"] in ("ccw", "cw")
            assert (g["rocker_turns_on_rise"] == d["rotation"]) == (d["swing"] == "same"), n
            if d["closure"] == "force" and d["pivot_move"] is None:  # METHOD: the smaller r0 turns with the cam
                assert d["swing"] == "same", n
        else:
            assert g["pivot_mm"] is None and g["axis_point_mm"] == [d["e_mm"], 0.0]


def test_curve_closed_and_radii(exported):
    for n, d in exported.items():
        pts = np.array(d["pitch_curve_mm"])
        assert np.array_equal(pts[0], pts[-1]), f"variant {n}: pitch curve not closed"
        rad = np.hypot(pts[:, 0], pts[:, 1])
        assert rad.min() == pytest.approx(d["r0_mm"], abs=2e-4), n
        assert rad.max() == pytest.approx(d["far_dwell_radius_mm"], abs=2e-4), n
        assert rad[0] == pytest.approx(d["r0_mm"], abs=2e-4), n  # B0 on the base circle


def test_inverted_motion_reproduces_the_follower_law(exported):
    """B(φ) = R(±φ)·P(φ) stays on the follower's axis (circle) and moves by the law's stroke."""
    for n, d in exported.items():
        phi, pts, b, sense = inverted(d)
        g = d["follower_in_curve_frame"]
        frac = fraction(d, phi)
        if d["follower"] == "rocker":
            c = np.array(g["pivot_mm"])
            cb = b - c
            # on the rocker's circle about the fixed pivot
            assert np.abs(np.hypot(cb[:, 0], cb[:, 1]) - d["l_bc_mm"]).max() < 5e-4, f"variant {n}: B leaves the rocker"
            cb0 = cb[0]
            gamma = np.degrees(np.arctan2(cb0[0] * cb[:, 1] - cb0[1] * cb[:, 0], (cb0 * cb).sum(axis=1)))
            turn = 1.0 if g["rocker_turns_on_rise"] == "ccw" else -1.0
            want = turn * d["gamma_max_deg"] * frac
            assert np.abs(gamma - want).max() < 2e-3, f"variant {n}: γ(φ) off the law by {np.abs(gamma - want).max():.4f}°"
            # the rise moves B along +y at B0
            dir0 = np.array([-cb0[1], cb0[0]]) * turn
            assert dir0[1] > 0 and abs(dir0[0]) < 1e-5 * d["l_bc_mm"]
            s_b = np.radians(turn * gamma) * d["l_bc_mm"]  # (1.6) S_B = γ·l_BC, γ counted on the rise
            assert s_b.max() == pytest.approx(math.radians(d["gamma_max_deg"]) * d["l_bc_mm"], abs=1e-3)
        else:
            e = g["axis_point_mm"][0]
            assert np.abs(b[:, 0] - e).max() < 5e-4, f"variant {n}: B leaves the axis x = e by {np.abs(b[:, 0] - e).max():.4f} mm"
            s = b[:, 1] - b[0, 1]
            want = d["s_max_mm"] * frac
            assert np.abs(s - want).max() < 5e-4, f"variant {n}: S(φ) off the law by {np.abs(s - want).max():.4f} mm"
            assert s.max() == pytest.approx(d["s_max_mm"], abs=5e-4)


def test_pressure_angle_from_the_curve(exported):
    """ν ≤ ν_max (+0.05°) on the constrained phases, and the exported maxima agree."""
    for n, d in exported.items():
        phi, pts, b, sense = inverted(d)
        got = {}
        for phase, pieces in smooth_pieces(d).items():
            got[phase] = max(
                float(pressure_angles(d, phi, b, sense, tangents(pts, i0, i1), np.arange(i0, i1 + 1)).max())
                for i0, i1 in pieces
            )
        phases = ("rise",) if d["closure"] == "force" else ("rise", "return")
        for phase in phases:
            assert got[phase] <= d["nu_max_deg"] + PRESSURE_TOL_DEG, (
                f"variant {n} ({d['rotation']}): ν on the {phase} = {got[phase]:.3f}° > ν_max = {d['nu_max_deg']}°"
            )
        for phase in ("rise", "return"):
            assert got[phase] == pytest.approx(d["pressure_angle_max_deg"][phase], abs=PRESSURE_TOL_DEG), (
                f"variant {n}: {phase} ν from the curve {got[phase]:.3f}° vs exported {d['pressure_angle_max_deg'][phase]}°"
            )


def test_profile_angles_from_the_curve(exported):
    """ψ from the polar angles of the exported curve; their sum is φ_р (1.4), ψ_дс = φ_дс."""
    for n, d in exported.items():
        pts = np.array(d["pitch_curve_mm"])
        step = d["pitch_curve_step_deg"]
        sense = 1.0 if d["rotation"] == "ccw" else -1.0
        th = np.degrees(np.unwrap(np.arctan2(pts[:, 1], pts[:, 0])))
        ph = d["phases_deg"]
        idx = [round(a / step) for a in (0.0, ph["rise"], ph["rise"] + ph["far_dwell"], ph["working"])]
        swept = -sense * np.diff(th[idx])  # the curve runs round against the rotation
        psi = d["psi_deg"]
        assert swept == pytest.approx([psi["rise"], psi["far_dwell"], psi["return"]], abs=2e-3), n
        assert sum(swept) == pytest.approx(ph["working"], abs=2e-3), n
        assert swept[1] == pytest.approx(ph["far_dwell"], abs=2e-3), n


def derivatives(pts, i0, i1):
    """dP/dφ and d²P/dφ² at points i0..i1 (local quartic over CURVATURE_FIT_POINTS samples)."""
    return local_fit(pts, i0, i1, CURVATURE_FIT_POINTS)


def test_undercut_verdict_from_the_curve(exported):
    """Radius of curvature of the exported pitch curve (convex > 0, seen from the cam centre):
    the roller 0.2·r0 (1.28) undercuts exactly when it is not below the smallest convex radius
    (groove: the smallest concave one too)."""
    for n, d in exported.items():
        pts = np.array(d["pitch_curve_mm"])[:-1]
        step = d["pitch_curve_step_deg"]
        ph = d["phases_deg"]
        marks = [0.0, ph["rise"], ph["rise"] + ph["far_dwell"], ph["working"], 360.0]
        if d["law"] == 1:
            marks += [ph["rise"] / 2, ph["rise"] + ph["far_dwell"] + ph["return"] / 2]
        idx = sorted({round(a / step) for a in marks})
        rho = []
        for i0, i1 in zip(idx[:-1], idx[1:]):
            ext = np.concatenate([pts, pts[:1]])  # index len(pts) is the closing point
            d1, d2 = derivatives(ext, i0, i1)
            cross = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
            turn = 1.0 if d["rotation"] == "ccw" else -1.0  # the curve runs against the rotation
            with np.errstate(divide="ignore"):
                rho.append(np.hypot(d1[:, 0], d1[:, 1]) ** 3 / (-turn * cross))
        rho = np.concatenate(rho)
        convex = rho[rho > 0].min()
        assert convex == pytest.approx(d["rho_min_mm"], rel=RHO_TOL), n
        limit = convex
        if d["closure"] == "form" and (rho < 0).any():
            concave = -rho[rho < 0].max()
            assert concave == pytest.approx(d["rho_min_concave_mm"], rel=RHO_TOL), n
            limit = min(limit, concave)
        # (1.28) 0.2·r0, limited to 0.8·ρ_lim (issue 8): the curve's own limit decides
        assert d["roller_book_mm"] == pytest.approx(0.2 * d["r0_mm"], abs=1e-3)
        assert d["roller_mm"] == pytest.approx(min(0.2 * d["r0_mm"], 0.8 * limit), rel=RHO_TOL), n
        assert d["roller_max_mm"] == pytest.approx(limit, rel=RHO_TOL), n
        exact = min(d["rho_min_mm"], d["rho_min_concave_mm"]) if d["closure"] == "form" and d["rho_min_concave_mm"] else d["rho_min_mm"]
        assert d["roller_max_mm"] == pytest.approx(exact, abs=1e-3), n
        assert d["undercut"] == (d["roller_mm"] >= d["roller_max_mm"]), n
        if abs(d["roller_mm"] / limit - 1.0) > RHO_TOL:  # the curve alone decides
            assert d["undercut"] == (d["roller_mm"] >= limit), n
        # issue 8: the carried cam never undercuts — the roller is below the curve's own limit
        assert d["roller_mm"] < limit * (1 - RHO_TOL), f"variant {n}: roller {d['roller_mm']} mm vs ρ_lim {limit:.3f} mm"
        assert d["undercut"] is False and d["checks"]["undercut_ok"] is True, n


def test_rocker_pivot_clear_of_the_exported_profile(exported):
    """Issue 8: the rocker's pivot lies outside every point of the cam body — the working profile
    (spring) or the groove's outer wall — taken from the exported curves alone."""
    for n, d in exported.items():
        if d["follower"] != "rocker":
            assert d["checks"]["pivot_ok"] is None
            continue
        wall = d["groove_outer_profile_mm"] if d["closure"] == "form" else d["working_profile_mm"]
        body = np.hypot(*np.array(wall, dtype=float).T).max()
        pivot = math.hypot(*d["follower_in_curve_frame"]["pivot_mm"])
        assert pivot > body, f"variant {n}: pivot at {pivot:.2f} mm inside the cam's sweep {body:.2f} mm"
        assert d["checks"]["pivot_ok"] is True and d["checks"]["all_ok"] is True, n
