"""Velocities and accelerations of the slotted-link mechanism by differentiating the vector loops.

First the transfer functions (аналоги скоростей и ускорений): derivatives with respect to the
crank angle φ21, which depend on the geometry only. Then, for a crank turning at ω21 with angular
acceleration ε21 at the position considered, every velocity is (d/dφ)·ω21 and every acceleration
(d²/dφ²)·ω21² + (d/dφ)·ε21.

Loop 1, A − O41 = ρ·u with u = (sin φ41, cos φ41) and n = du/dφ41 = (cos φ41, −sin φ41):
    v_A = ρ'·u + ρ·φ41'·n                    -> ρ' = v_A·u,  φ41' = v_A·n / ρ
    a_A = (ρ'' − ρ·φ41'²)·u + (ρ·φ41'' + 2·ρ'·φ41')·n
The term 2·ρ'·φ41' is the Coriolis acceleration 2·ω4·v_rel of the block relative to the turning
link. Loop 2, B − C = r3·(cos ψ, sin ψ) with C on y = b:
    y_B' = r3·cos ψ·ψ',        x_C' = x_B' + r3·sin ψ·ψ'
    y_B'' = −r3·sin ψ·ψ'² + r3·cos ψ·ψ'',   x_C'' = x_B'' + r3·cos ψ·ψ'² + r3·sin ψ·ψ''
These are the derivatives of seed 003's eq. (3); its closed forms (4), (5) give the same numbers
wherever h + r1·cos φ21 > 0 and the crank turns uniformly (checked in the tests).
φ41, ω4, ε4 are measured like φ21 (from +y towards +x); ψ counter-clockwise from +x.
"""

from __future__ import annotations

import numpy as np

from ..records import record
from .geometry import Geometry, Positions


@record
class Transfer:
    """First and second derivatives with respect to φ21 (per radian of crank turn)."""

    link1: np.ndarray  # dφ41/dφ21 [-]
    link2: np.ndarray  # d²φ41/dφ21² [-]
    rho1: np.ndarray  # dρ/dφ21 [m]
    rho2: np.ndarray  # d²ρ/dφ21² [m]
    psi1: np.ndarray  # dψ/dφ21 [-]
    psi2: np.ndarray  # d²ψ/dφ21² [-]
    x1: np.ndarray  # dx_C/dφ21 [m]
    x2: np.ndarray  # d²x_C/dφ21² [m]


def transfer(g: Geometry, p: Positions) -> Transfer:
    """Transfer functions of the link, the block and the ram at the positions `p`.

    >>> from .geometry import make_geometry, positions
    >>> import math
    >>> g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    >>> t = transfer(g, positions(g, 0.0))   # A at the top: ρ = r1 + h, the link follows the crank
    >>> round(float(t.link1), 12), round(float(t.rho1), 12)
    (0.714285714286, 0.0)
    """
    phi, link, rho, psi = p.phi, p.link, p.rho, p.psi
    u = np.stack([np.sin(link), np.cos(link)], axis=-1)
    n = np.stack([np.cos(link), -np.sin(link)], axis=-1)
    va = g.r1 * np.stack([np.cos(phi), -np.sin(phi)], axis=-1)  # dA/dφ21
    aa = -g.r1 * np.stack([np.sin(phi), np.cos(phi)], axis=-1)  # d²A/dφ21²
    rho1 = np.sum(va * u, axis=-1)
    link1 = np.sum(va * n, axis=-1) / rho
    rho2 = np.sum(aa * u, axis=-1) + rho * link1 * link1
    link2 = (np.sum(aa * n, axis=-1) - 2.0 * rho1 * link1) / rho
    vb = (g.r2 * link1)[..., None] * n
    ab = (g.r2 * link2)[..., None] * n - (g.r2 * link1 * link1)[..., None] * u
    cos_psi, sin_psi = np.cos(psi), np.sin(psi)
    psi1 = vb[..., 1] / (g.r3 * cos_psi)
    x1 = vb[..., 0] + g.r3 * sin_psi * psi1
    psi2 = (ab[..., 1] + g.r3 * sin_psi * psi1 * psi1) / (g.r3 * cos_psi)
    x2 = ab[..., 0] + g.r3 * cos_psi * psi1 * psi1 + g.r3 * sin_psi * psi2
    return Transfer(link1, link2, rho1, rho2, psi1, psi2, x1, x2)


@record
class Motion:
    """Velocities and accelerations for a crank at ω21, ε21 (arrays like the positions)."""

    omega_link: np.ndarray  # ω4 = dφ41/dt [rad/s]
    eps_link: np.ndarray  # ε4 [rad/s²]
    v_rel: np.ndarray  # dρ/dt, the block's sliding velocity along the link, + away from O41 [m/s]
    a_rel: np.ndarray  # d²ρ/dt² [m/s²]
    a_cor: np.ndarray  # 2·ω4·v_rel, Coriolis acceleration of the block (along n) [m/s²]
    omega_rod: np.ndarray  # dψ/dt [rad/s] (counter-clockwise)
    eps_rod: np.ndarray  # [rad/s²]
    v_c: np.ndarray  # ram velocity dx_C/dt [m/s]
    a_c: np.ndarray  # ram acceleration [m/s²]


def motion(t: Transfer, omega: float, eps: float = 0.0) -> Motion:
    """Velocities = transfer·ω21, accelerations = transfer''·ω21² + transfer'·ε21 (chain rule).

    >>> from .geometry import make_geometry, positions
    >>> g = make_geometry(0.10, 0.04, 0.0, 0.08, 0.30, -0.04)
    >>> m = motion(transfer(g, positions(g, 0.0)), 10.0)
    >>> round(float(m.omega_link), 9), round(float(m.v_c), 9)   # ω4 = ω21·r1/(r1 + h)
    (7.142857143, 0.571428571)
    """
    w2 = omega * omega
    omega_link = t.link1 * omega
    v_rel = t.rho1 * omega
    return Motion(
        omega_link=omega_link,
        eps_link=t.link2 * w2 + t.link1 * eps,
        v_rel=v_rel,
        a_rel=t.rho2 * w2 + t.rho1 * eps,
        a_cor=2.0 * omega_link * v_rel,
        omega_rod=t.psi1 * omega,
        eps_rod=t.psi2 * w2 + t.psi1 * eps,
        v_c=t.x1 * omega,
        a_c=t.x2 * w2 + t.x1 * eps,
    )
