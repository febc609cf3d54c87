"""The certified smallest cam that keeps the book's roller 0.2·r0 (tmm_cli/cam/book_roller.py),
checked against an independent brute force: the mechanism rebuilt from the motion law here
(tests/test_cam_design.py's model), the pressure angle from the relative velocity, the radius of
curvature of the pitch curve from circles through three neighbouring points. No centre the brute
force finds may beat the certified bound; the bound itself is reached."""

import math

import numpy as np
import pytest

from tmm_cli.cam.design import CamChoice, design_cam
from tmm_cli.render.data.cam import cam_to_json

from test_cam_design import constrained_angles, pressure_angles, roller_path


def _rho_limit(v, centre, pivot, kappa, sgn, step=0.25):
    """Smallest convex (groove: also concave) radius of curvature of the pitch curve [m]."""
    phi = np.arange(0.0, 360.0, step)
    b = roller_path(v, (0.0, 0.0), pivot, kappa, phi)
    rel = b - np.asarray(centre)
    a = -sgn * np.radians(phi)  # the cam frame turns back by the cam angle
    p = np.stack([np.cos(a) * rel[:, 0] - np.sin(a) * rel[:, 1], np.sin(a) * rel[:, 0] + np.cos(a) * rel[:, 1]], axis=-1)
    p0, p1, p2 = np.roll(p, 1, axis=0), p, np.roll(p, -1, axis=0)
    ab, bc, ca = (np.hypot(*(x - y).T) for x, y in ((p0, p1), (p1, p2), (p2, p0)))
    cross = (p1 - p0)[:, 0] * (p2 - p1)[:, 1] - (p1 - p0)[:, 1] * (p2 - p1)[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = ab * bc * ca / (2 * np.abs((p1 - p0)[:, 0] * (p2 - p0)[:, 1] - (p1 - p0)[:, 1] * (p2 - p0)[:, 0]))
    convex = sgn * cross < 0  # the curve runs round O against the rotation
    lim = rho[convex].min()
    if v.closure == "form" and (~convex).any():
        lim = min(lim, rho[~convex].min())
    return lim


def _brute(v, pivot, centre_hint, r_hint):
    """Smallest |O B0| on grids (coarse, then zoomed) with ν ≤ ν_max and 0.2·|O| < ρ_lim. The
    fixed frame: B0 at the origin, B rising along +y, the cam turning as n_k says; the pivot is
    the reported one (l_BC away on the x axis)."""
    sgn = 1.0 if v.n_cam_rpm > 0 else -1.0
    kappa = 1.0 if pivot[0] < 0 else -1.0  # B rises along +y at B0
    phi = constrained_angles(v, 0.25)

    def ok_nu(cx, cy):
        return np.array([pressure_angles(v, (x, y), (0.0, 0.0), pivot, kappa, phi).max() <= v.nu_max_deg
                         for x, y in zip(cx, cy)])

    best = None
    cx0, cy0, half = 0.0, 0.0, 1.05 * r_hint  # first the whole disc round B0, then zoomed
    for n in (43, 25, 25, 25):
        xs, ys = np.linspace(cx0 - half, cx0 + half, n), np.linspace(cy0 - half, cy0 + half, n)
        gx, gy = (a.ravel() for a in np.meshgrid(xs, ys))
        order = np.argsort(np.hypot(gx, gy))
        gx, gy = gx[order], gy[order]
        nu_ok = ok_nu(gx, gy)
        for x, y in zip(gx[nu_ok], gy[nu_ok]):
            if 0.2 * math.hypot(x, y) < _rho_limit(v, (x, y), pivot, kappa, sgn):
                if best is None or math.hypot(x, y) < best:
                    best = math.hypot(x, y)
                    cx0, cy0 = x, y
                break
        half = half / 6 if best is not None else half
        if best is None:  # the disc grid missed the thin working sliver: zoom on the certified centre
            cx0, cy0, half = centre_hint[0], centre_hint[1], 0.05 * r_hint
    return best


@pytest.mark.parametrize("number, swing", [(19, None), (3, "same"), (7, "same"), (4, None)])
def test_certified_smallest_cam_for_the_book_roller(table, number, swing):
    v = table[number]
    cam = design_cam(v, choice=CamChoice(swing=swing) if swing else None)
    fix = cam.book_roller_fix
    assert fix is not None and fix.certified
    d = cam_to_json(cam, "en")
    assert d["undercut_fix"]["certified"] is True
    assert d["undercut_fix"]["r0_mm"] == pytest.approx(fix.r0_m * 1000, abs=1e-3)
    # the zone frame is the brute force's fixed frame (B0 at the origin, true rotation sense)
    pivot = cam.sizing.pivot
    assert math.hypot(*pivot) == pytest.approx(v.l_bc_m) and pivot[1] == 0.0
    assert (pivot[0] < 0) == ((cam.sizing.swing == "same") == v.ccw)  # the stated swing
    brute = _brute(v, pivot, fix.centre, fix.r0_m)
    assert brute is not None
    bound = fix.r0_m / (1 + fix.rel_tol)  # the certified R (the fix is shown moved out by rel_tol)
    # nothing below R·(1 − rel_tol), up to the two models' own sampling (0.25° of cam angle)
    slack = fix.rel_tol + 1e-3
    assert brute >= bound * (1 - slack), f"brute force found r0 = {brute * 1000:.3f} mm < {bound * 1000:.3f} mm"
    assert brute <= bound * 1.01
    if swing is None:  # the carried design: the note states the tolerance of the proof in per cent
        note = next(x for x in cam.notes if x.code.startswith("cam_book_roller_fix"))
        assert note.kwargs["tol_pct"] == pytest.approx(fix.rel_tol * 100) and fix.rel_tol == 1e-3


def test_the_shown_options_carry_a_working_cam(table):
    """The note's options (--r0 --l-oc --swing --roller) reproduce a cam with no undercut and ν ≤ ν_max."""
    v = table[19]
    cam = design_cam(v)
    f = cam.book_roller_fix
    text = [n for n in cam.notes if n.code == "cam_book_roller_fix_rocker"][0].kwargs
    r2 = design_cam(v, choice=CamChoice(r0_mm=text["r0_mm"], l_oc_mm=text["geo_mm"], swing=text["swing"],
                                        roller_mm=text["roller_mm"]))
    assert r2.checks.undercut_ok and r2.checks.nu_rise_ok and r2.checks.nu_return_ok
    assert text["roller_mm"] == pytest.approx(0.2 * text["r0_mm"], abs=0.011)
    assert f.r0_m * 1000 <= text["r0_mm"] + 1e-9
