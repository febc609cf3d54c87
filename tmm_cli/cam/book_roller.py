"""The smallest cam that keeps the book's roller r_р = 0.2·r0 (1.28) without undercut — certified.

The program carries r_р = min(0.2·r0, 0.8·ρ_min) (:mod:`tmm_cli.cam.profile`); where the book's
0.2·r0 would undercut (variant 19, or a student's forced swing of 3, 7, 11), it shows beside it
the other way out: a larger cam. This module finds the smallest base radius r0 = |O B0| over the
whole pressure-angle zone F (the convex region of :mod:`tmm_cli.cam.sizing`) at which a roller
λ·r0 (λ = 0.2) works, and proves that no centre of F with r0 < R·(1 − rel_tol) does.

Condition. In the canonical frame (B0 at the origin) the pitch curve for a cam centre O has
Q1 = A(φ) + J·O and Q2 = C(φ) + O, with A = B′ − J·B and C = B″ − 2J·B′ − B known from the
follower law (J: rotation by +90°). Its radius of curvature is ρ = |Q1|³/(−Q1 × Q2) (> 0 on convex
stretches). The roller works at O iff for every cam angle φ

    G(φ, O) = |Q1|³ − λ·|O|·c(φ, O) > 0,  c = −Q1 × Q2 (spring),  c = |Q1 × Q2| (groove, both walls).

Why the search cannot miss the smallest r0 (branch and bound over squares of the plane):

* a square S (centre O_c, half-side h) with every O ∈ S written O = O_c + δ, |δ| ≤ √2·h, has, at a
  fixed φ, |Q1| ≤ |Q1c| + √2·h, |O| ≥ |O_c| − √2·h and
  −Q1 × Q2 = −Q1c × Q2c − Q1c × δ − Jδ × Q2c + |δ|² ≥ c_c − √2·h·(|Q1c| + |Q2c|)
  (groove: |Q1 × Q2| ≥ |Q1c × Q2c| − √2·h·(|Q1c| + |Q2c|) − 2h²), so
  G(φ, O) ≤ (|Q1c| + √2h)³ − λ·(|O_c| − √2h)₊·(c_lower)₊ for *every* O in S. If this upper bound is
  negative at one sampled φ, every centre in S undercuts — one cam angle is witness enough, so
  the sampling in φ needs no continuity argument;
* a square is also dropped when it lies outside F (beyond one edge of the zone polygon, checked at
  its corners) or when its nearest point to B0 is at least R·(1 − rel_tol), R the best r0 found;
* every other square is split in four. Squares that get below h_min without a verdict are
  resolved by evaluating a 5 × 5 grid inside them; any left undecided are counted in
  ``unresolved`` (zero for every case the tests run) and ``certified`` is then False.

So the dropped squares cover every point of F with r0 < R·(1 − rel_tol): none of them works, and R
is attained by a centre verified to work on a 0.05° grid of cam angles (the grid the profile's own
undercut check uses). The search starts from a working centre on the ray from B0 through the
zone's nearest point, so R is finite from the start.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .motion import CamProgram
from .sizing import Sizing, _inside, follower_state, rot90

WITNESS_STEP_DEG = 0.25  # cam angles tried as witnesses of an undercut
CHECK_STEP_DEG = 0.05  # cam angles on which a found centre is verified
CAP_R0 = 4.0  # the search covers the zone up to this many times the smallest r0


@record
class RollerFix:
    """The smallest cam keeping a roller ratio·r0, in the canonical frame [m]."""

    ratio: float
    r0_m: float
    centre_canonical: tuple[float, float]
    rel_tol: float
    certified: bool
    cells: int  # squares examined
    unresolved: int  # squares left without a verdict (0: the bound is proven)


def _law_terms(program: CamProgram, phi: np.ndarray, *, rocker: bool, l_bc_m: float | None, sigma: int):
    st = follower_state(program, phi, rocker=rocker, l_bc_m=l_bc_m, sigma=sigma)
    a = st.b1 - rot90(st.b)
    c = st.b2 - 2.0 * rot90(st.b1) - st.b
    return a, c


def _phis(program: CamProgram, step_deg: float) -> np.ndarray:
    n = int(round(360.0 / step_deg))
    phi = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    eps = 1e-9
    marks = [0.0, program.phi_rise, program.return_start, program.phi_working, program.phi_rise / 2,
             program.return_start + program.phi_return / 2]
    extra = np.array([m + d for m in marks for d in (-eps, eps)])
    return np.concatenate([phi, np.mod(extra, 2.0 * math.pi)])


def _cross(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _g_min(points: np.ndarray, a: np.ndarray, c: np.ndarray, ratio: float, groove: bool) -> np.ndarray:
    """min over the sampled φ of G(φ, O) for each point O (rows of `points`)."""
    out = np.empty(len(points))
    for i0 in range(0, len(points), 64):
        o = points[i0 : i0 + 64]
        q1 = a[None] + rot90(o)[:, None, :]
        q2 = c[None] + o[:, None, :]
        cr = _cross(q1, q2)
        cc = np.abs(cr) if groove else -cr
        g = np.hypot(q1[..., 0], q1[..., 1]) ** 3 - ratio * np.hypot(o[:, 0], o[:, 1])[:, None] * cc
        out[i0 : i0 + 64] = g.min(axis=1)
    return out


def _proven_bad(centres: np.ndarray, h: np.ndarray, a: np.ndarray, c: np.ndarray, ratio: float, groove: bool) -> np.ndarray:
    """True where the interval bound shows G < 0 for every point of the square at some sampled φ."""
    out = np.zeros(len(centres), dtype=bool)
    for i0 in range(0, len(centres), 64):
        o = centres[i0 : i0 + 64]
        r = (math.sqrt(2.0) * h[i0 : i0 + 64])[:, None]
        q1 = a[None] + rot90(o)[:, None, :]
        q2 = c[None] + o[:, None, :]
        n1 = np.hypot(q1[..., 0], q1[..., 1])
        n2 = np.hypot(q2[..., 0], q2[..., 1])
        cr = _cross(q1, q2)
        if groove:
            c_low = np.abs(cr) - r * (n1 + n2) - r * r
        else:
            c_low = -cr - r * (n1 + n2)
        o_low = np.maximum(np.hypot(o[:, 0], o[:, 1])[:, None] - r, 0.0)
        g_up = (n1 + r) ** 3 - ratio * o_low * np.maximum(c_low, 0.0)
        out[i0 : i0 + 64] = (g_up < 0.0).any(axis=1)
    return out


def _edges(poly: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Outward normals n and offsets d of a convex polygon's edges: inside ⇔ n·x ≤ d for all."""
    nxt = np.roll(poly, -1, axis=0)
    e = nxt - poly
    area = float(np.sum(_cross(poly, nxt)))
    n = np.stack([e[:, 1], -e[:, 0]], axis=-1) * (1.0 if area > 0 else -1.0)
    return n, (n * poly).sum(axis=1)


def smallest_r0_for_roller(program: CamProgram, z: Sizing, *, rocker: bool, l_bc_m: float | None,
                           ratio: float = 0.2, rel_tol: float = 1e-3, max_cells: int = 400_000) -> RollerFix | None:
    """The smallest r0 over the pressure-angle zone of `z` (its swing) at which a roller ratio·r0
    does not undercut, with the certificate described in the module docstring; None when no
    centre of the zone up to CAP_R0 = 4 times the smallest r0 works.

    >>> from tmm_cli.cam.sizing import size_cam
    >>> p = CamProgram(law=3, stroke=0.04, phi_rise=math.radians(60), phi_far=0.2, phi_return=math.radians(60))
    >>> z = size_cam(p, rocker=False, l_bc_m=None, nu_max_deg=40, closure="force", ccw=True)
    >>> fix = smallest_r0_for_roller(p, z, rocker=False, l_bc_m=None)
    >>> fix.certified, fix.r0_m >= z.r0_m
    (True, True)
    """
    groove = z.closure == "form"
    a_w, c_w = _law_terms(program, _phis(program, WITNESS_STEP_DEG), rocker=rocker, l_bc_m=l_bc_m, sigma=z.sigma)
    a_c, c_c = _law_terms(program, _phis(program, CHECK_STEP_DEG), rocker=rocker, l_bc_m=l_bc_m, sigma=z.sigma)
    poly = z.polygon_canonical
    normals, offsets = _edges(poly)

    def good(pts: np.ndarray) -> np.ndarray:
        pts = np.atleast_2d(pts)
        ok = _inside(poly, pts)
        if ok.any():
            ok[ok] = _g_min(pts[ok], a_c, c_c, ratio, groove) > 0.0
        return ok

    # a first working centre: out along the ray from B0 through the zone's nearest point, then
    # bisected between the last failing and the first working sample (a better start, not the proof)
    o0 = np.asarray(z.centre_canonical, dtype=float)
    ts = np.concatenate([np.linspace(1.0, 2.0, 41), np.linspace(2.05, 20.0, 360)])
    ok_t = [t for t in ts if good(o0 * t)[0]]
    best, big_r = None, CAP_R0 * float(np.hypot(*o0))  # no working centre yet: search up to the cap
    if ok_t:
        hi_t = float(ok_t[0])
        lo_t = float(ts[max(int(np.searchsorted(ts, hi_t)) - 1, 0)])
        if lo_t < hi_t:
            for _ in range(40):
                mid = 0.5 * (lo_t + hi_t)
                lo_t, hi_t = (lo_t, mid) if good(o0 * mid)[0] else (mid, hi_t)
        best = o0 * hi_t
        big_r = float(np.hypot(*best))

    # branch and bound over squares covering the zone within the disc |O| < R
    x0, y0 = np.maximum(poly.min(axis=0), -big_r)
    x1, y1 = np.minimum(poly.max(axis=0), big_r)
    side = max(x1 - x0, y1 - y0)
    n0 = 16
    h0 = side / (2 * n0)
    gx, gy = np.meshgrid(x0 + h0 * (2 * np.arange(n0) + 1), y0 + h0 * (2 * np.arange(n0) + 1))
    cells = np.stack([gx.ravel(), gy.ravel()], axis=-1)
    halves = np.full(len(cells), h0)
    h_min = rel_tol * z.r0_m / 16.0
    examined = unresolved = 0
    while len(cells):
        examined += len(cells)
        if examined > max_cells:
            unresolved += len(cells)
            break
        r = math.sqrt(2.0) * halves
        near = np.hypot(cells[:, 0], cells[:, 1]) - r < big_r * (1.0 - rel_tol)
        outside = ((cells @ normals.T) - offsets[None] - halves[:, None] * np.abs(normals).sum(axis=1)[None] > 0.0).any(axis=1)
        keep = near & ~outside
        cells, halves = cells[keep], halves[keep]
        if not len(cells):
            break
        bad = _proven_bad(cells, halves, a_w, c_w, ratio, groove)
        cells, halves = cells[~bad], halves[~bad]
        if not len(cells):
            break
        ok = good(cells)
        if ok.any():
            r_ok = np.where(ok, np.hypot(cells[:, 0], cells[:, 1]), np.inf)
            k = int(np.argmin(r_ok))
            if r_ok[k] < big_r:
                big_r, best = float(r_ok[k]), cells[k].copy()
        small = halves < h_min
        if small.any():  # resolve tiny squares by a 5 × 5 grid inside them
            u = np.linspace(-1.0, 1.0, 5)
            for cc, hh in zip(cells[small], halves[small]):
                pts = np.array([[cc[0] + hh * a, cc[1] + hh * b] for a in u for b in u])
                pts = pts[np.hypot(pts[:, 0], pts[:, 1]) < big_r * (1.0 - rel_tol)]
                if not len(pts):
                    continue
                g = good(pts)
                if g.any():
                    rr = np.where(g, np.hypot(pts[:, 0], pts[:, 1]), np.inf)
                    j = int(np.argmin(rr))
                    big_r, best = float(rr[j]), pts[j].copy()
                else:
                    unresolved += 1
            cells, halves = cells[~small], halves[~small]
        q = halves / 2.0
        cells = np.concatenate([cells + np.stack([sx * q, sy * q], axis=-1) for sx in (-1, 1) for sy in (-1, 1)])
        halves = np.tile(q, 4)
    if best is None:
        return None
    return RollerFix(ratio=ratio, r0_m=big_r, centre_canonical=(float(best[0]), float(best[1])), rel_tol=rel_tol,
                     certified=unresolved == 0, cells=examined, unresolved=unresolved)
