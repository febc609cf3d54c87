"""The drawing scale of the cam profile, §1.4: Table 1.1 and the conversions (1.26), (1.27).

The profile is drawn at one of the standard engineering scales M (Table 1.1), each with its linear
scale k_Sk [m/mm]. The program picks the largest (most detailed) one at which the whole
construction — the pitch curve dilated by the roller, which contains the working profile D1, the
groove's outer wall D2 (form closure) and every roller position, and for a rocker the circle of
its pivot positions C_i (radius l_OC about O), on which the inversion is built — fits a square
drawing field of DRAWING_FIELD_MM (the profile field of sheet 3 keeps that square free). A cam
too large even at 1:10 takes the next reductions of ГОСТ 2.302 (1:15, 1:20 …) and is flagged.

This scale (``ProfileDrawing.scale`` / ``k_sk``) is the one source for every drawing of the
profile: sheet 3 draws at it, the note states it.

The lengths the student lays off on the sheet follow from the diagram and sizing scales:

* (1.26) y_Sik = (k_S/k_Sk)·y_Si [mm]: a follower displacement drawn y_Si [mm] on the displacement
  diagram (scale k_S, (1.11), or for a rocker the roller-centre scale k_S_B = k_γ·l_BC, (1.18)).
* (1.27) x_ik = (k_S′/k_Sk)·x_i [mm]: a main size drawn x_i [mm] in the sizing construction of §1.3
  (scale k_S′). The book's §1.3.1 builds the sizing in the diagram's own scale, so the program takes
  k_S′ = k_S (for a rocker k_S′ = k_S_B); this is stated as an assumption.

Both reduce to l/k_Sk for a length l [m]; they are kept in the book's two-step form so that the
intermediate sizes y_Si, x_i can be checked against the student's diagrams.
"""

from __future__ import annotations

import math

import numpy as np

from ..records import record
from .motion import Motion
from .profile import Profile
from .sizing import Sizing

# Table 1.1: standard scales M and their linear scales k_Sk [m/mm], coarsest first.
STANDARD_SCALES: tuple[tuple[str, float], ...] = (
    ("1:10", 0.01),
    ("1:5", 0.005),
    ("1:2", 0.002),
    ("1:1", 0.001),
    ("2:1", 0.0005),
    ("5:1", 0.0002),
    ("10:1", 0.0001),
)
# ГОСТ 2.302 reductions beyond Table 1.1, for a cam that does not fit at 1:10 (flagged, not raised)
BEYOND_TABLE: tuple[tuple[str, float], ...] = (
    ("1:15", 0.015), ("1:20", 0.02), ("1:25", 0.025), ("1:40", 0.04), ("1:50", 0.05), ("1:75", 0.075),
    ("1:100", 0.1),
)
DRAWING_FIELD_MM = 250.0  # side of the square field for the profile on sheet 3 (assumption)


def drawn_mm(length_m: float, k_diagram: float, k_sk: float) -> float:
    """A length l [m] drawn x_i = l/k [mm] at scale k [m/mm], redrawn at k_Sk: (1.26), (1.27).

    x_ik = (k/k_Sk)·x_i [mm]; equals l/k_Sk.

    >>> drawn_mm(0.05, 0.000625, 0.001)  # 50 mm: 80 mm on the diagram, 50 mm at M 1:1
    50.0
    >>> round(drawn_mm(0.05, 0.000625, 0.0005), 9)  # M 2:1
    100.0
    """
    x_i = length_m / k_diagram  # [mm] on the diagram / sizing construction
    return (k_diagram / k_sk) * x_i


def choose_scale(extent_m: float, field_mm: float = DRAWING_FIELD_MM) -> tuple[str, float, bool]:
    """Largest standard scale of Table 1.1 at which a drawing of `extent_m` [m] fits `field_mm` [mm].

    Returns (M, k_Sk [m/mm], fits); when even 1:10 is too small, the first reduction of ГОСТ 2.302
    beyond the table at which it fits (1:15 … 1:100) and fits = False.

    >>> choose_scale(0.180)  # 180 mm: 2:1 would need 360 mm
    ('1:1', 0.001, True)
    >>> choose_scale(0.100)
    ('2:1', 0.0005, True)
    >>> choose_scale(0.020)
    ('10:1', 0.0001, True)
    >>> choose_scale(3.0)  # 3 m: 300 mm at 1:10, 200 mm at 1:15
    ('1:15', 0.015, False)
    """
    best = None
    for label, k in STANDARD_SCALES:
        if extent_m / k <= field_mm * (1.0 + 1e-12):
            best = (label, k, True)
    if best is None:
        for label, k in BEYOND_TABLE:
            if extent_m / k <= field_mm * (1.0 + 1e-12):
                return label, k, False
        label, k = BEYOND_TABLE[-1]
        return label, k, False
    return best


def next_larger_scale(k_sk: float) -> tuple[str, float] | None:
    """The next more detailed scale of Table 1.1 (None after 10:1).

    >>> next_larger_scale(0.001)
    ('2:1', 0.0005)
    """
    ks = [k for _, k in STANDARD_SCALES]
    i = ks.index(k_sk)
    return STANDARD_SCALES[i + 1] if i + 1 < len(STANDARD_SCALES) else None


def profile_bbox(profile: Profile) -> tuple[float, float, float, float]:
    """(x_min, x_max, y_min, y_max) [m] of the cam with its roller, in the profile's cam frame.

    The pitch curve dilated by the roller radius bounds every roller position, the working profile
    D1 and the groove's outer wall D2; the envelopes are added anyway.
    """
    r = profile.roller_m
    pts = [profile.pitch - r, profile.pitch + r, profile.inner]
    if profile.outer is not None:
        pts.append(profile.outer)
    a = np.concatenate(pts)
    return float(a[:, 0].min()), float(a[:, 0].max()), float(a[:, 1].min()), float(a[:, 1].max())


def construction_bbox(profile: Profile, l_oc_m: float | None) -> tuple[float, float, float, float]:
    """(x_min, x_max, y_min, y_max) [m] of the profile construction: the cam with its roller
    (:func:`profile_bbox`) and, for a rocker, the circle of radius l_OC about O that carries the
    pivot positions C_i of the inversion.

    >>> from tmm_cli.variants import get_variant
    >>> from tmm_cli.cam.design import design_cam
    >>> r = design_cam(get_variant(3))  # a rocker: l_OC = 98.8 mm, the cam 144 mm wide
    >>> bb = construction_bbox(r.profile, r.sizing.l_oc_m)
    >>> round((bb[1] - bb[0]) * 1000, 1), round(2 * r.sizing.l_oc_m * 1000, 1)
    (197.6, 197.6)
    """
    x0, x1, y0, y1 = profile_bbox(profile)
    if l_oc_m is not None:
        x0, x1, y0, y1 = min(x0, -l_oc_m), max(x1, l_oc_m), min(y0, -l_oc_m), max(y1, l_oc_m)
    return x0, x1, y0, y1


@record
class DrawnSize:
    """One length as the student draws it: real [m], at k_S′ (x_i / y_Si) [mm], at k_Sk [mm]."""

    name: str  # r0, e, l_oc, l_bc, roller, stroke, ...
    formula: str  # "1.26" or "1.27"
    length_m: float
    at_k_s_mm: float  # x_i or y_Si
    drawn_mm: float  # x_ik or y_Sik


@record
class DrawnPosition:
    """(1.26) at one position of the motion table: B_i B'_i laid off on the profile drawing."""

    index: int
    phi_deg: float
    s_m: float  # S_i or S_B,i = γ_i·l_BC (arc) [m]
    y_s_mm: float  # y_Si = S_i/k_S, the diagram ordinate
    y_sk_mm: float  # y_Sik = (k_S/k_Sk)·y_Si, (1.26)
    chord_mm: float | None  # rocker: the exact chord 2·l_BC·sin(γ_i/2)/k_Sk (the book lays off y_Sik)


@record
class ProfileDrawing:
    """The profile's drawing scale (Table 1.1) and the sizes at it, (1.26)–(1.27)."""

    scale: str  # M, e.g. "1:1"
    k_sk: float  # [m/mm]
    k_s: float  # k_S of the displacement diagram [m/mm] (rocker: k_S_B, (1.18))
    k_s_prime: float  # k_S′ of the sizing construction [m/mm], taken = k_S
    field_mm: float
    bbox_m: tuple[float, float, float, float]  # x_min, x_max, y_min, y_max in the cam frame
    fits: bool  # False only if the construction exceeds the field even at 1:10 (a ГОСТ 2.302 reduction then)
    sizes: tuple[DrawnSize, ...]
    positions: tuple[DrawnPosition, ...]
    construction_bbox_m: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)  # + the pivot circle (rocker)

    @property
    def width_m(self) -> float:
        return self.bbox_m[1] - self.bbox_m[0]

    @property
    def height_m(self) -> float:
        return self.bbox_m[3] - self.bbox_m[2]

    @property
    def extent_m(self) -> float:
        """The larger side of the cam's bounding box [m]."""
        return max(self.width_m, self.height_m)

    @property
    def construction_extent_m(self) -> float:
        """The larger side of the construction's box [m] (the square field holds it at k_Sk)."""
        x0, x1, y0, y1 = self.construction_bbox_m
        return max(x1 - x0, y1 - y0)

    @property
    def extent_mm(self) -> tuple[float, float]:
        """Width and height of the drawn cam on the sheet [mm] at k_Sk."""
        return self.width_m / self.k_sk, self.height_m / self.k_sk

    def size(self, name: str) -> DrawnSize | None:
        return next((s for s in self.sizes if s.name == name), None)


def profile_drawing(motion: Motion, sizing: Sizing, profile: Profile, field_mm: float = DRAWING_FIELD_MM) -> ProfileDrawing:
    """Scale of the profile drawing (Table 1.1) and the main sizes and displacements at it, (1.26)–(1.27).

    >>> from tmm_cli.variants import Variant
    >>> from tmm_cli.cam.design import design_cam
    >>> d = design_cam(Variant(1, 1, None, 25.0, 800.0, 0.05, 1, 100.0, 20.0, 100.0)).drawing
    >>> d.scale, d.k_sk, d.size("stroke").drawn_mm  # S_max = 50 mm drawn 50 mm at M 1:1
    ('1:1', 0.001, 50.0)
    >>> d.size("stroke").at_k_s_mm  # y_Smax on the diagram, k_S = 0.05/80 m/mm
    80.0
    """
    sc = motion.scales
    rocker = motion.rocker
    l_bc = motion.l_bc_m
    k_s = sc.k_s_b if rocker else sc.k_s  # m/mm: (1.18) for the roller centre, else (1.11)
    k_sp = k_s  # k_S′ = k_S (§1.3.1 builds the sizing in the diagram's scale)
    bbox = profile_bbox(profile)
    cbox = construction_bbox(profile, sizing.l_oc_m if rocker else None)
    extent = max(cbox[1] - cbox[0], cbox[3] - cbox[2])
    label, k_sk, fits = choose_scale(extent, field_mm)

    def size(name: str, formula: str, length: float, k: float) -> DrawnSize:
        return DrawnSize(name, formula, float(length), float(length / k), float(drawn_mm(length, k, k_sk)))

    h = motion.program.stroke * (l_bc if rocker else 1.0)  # S_max, or S_B,max = γ_max·l_BC (1.6)
    sizes = [size("r0", "1.27", sizing.r0_m, k_sp)]
    if rocker:
        sizes += [size("l_oc", "1.27", sizing.l_oc_m, k_sp), size("l_bc", "1.27", l_bc, k_sp)]
    else:
        sizes.append(size("e", "1.27", sizing.e_m, k_sp))
    sizes += [
        size("roller", "1.27", profile.roller_m, k_sp),
        size("working_min_radius", "1.27", profile.working_min_radius_m, k_sp),
        size("far_dwell_radius", "1.27", profile.r_far_m, k_sp),
        size("stroke", "1.26", h, k_s),
    ]
    positions = []
    for row in motion.table:
        s = row.s_b_m if rocker else row.s
        chord = 2.0 * l_bc * math.sin(abs(row.s) / 2.0) / k_sk if rocker else None
        positions.append(DrawnPosition(row.index, row.phi_deg, float(s), float(s / k_s), float(drawn_mm(s, k_s, k_sk)), chord))
    return ProfileDrawing(
        scale=label,
        k_sk=k_sk,
        k_s=k_s,
        k_s_prime=k_sp,
        field_mm=field_mm,
        bbox_m=bbox,
        fits=fits,
        sizes=tuple(sizes),
        positions=tuple(positions),
        construction_bbox_m=cbox,
    )
