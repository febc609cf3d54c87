"""The whole course project for one variant: sheet 4 (gears) and sheet 3 (cam) in one result.

No printing, plotting or files here: :func:`run_project` calls the same core functions as the
``tmm cam`` and ``tmm gears`` commands and returns one frozen :class:`ProjectResult`.
"""

from __future__ import annotations

from .notes import Note
from .records import record
from .variants import Variant


@record
class ProjectResult:
    """Both sheets of one variant; `notes` gathers the notes of both, assumptions first."""

    variant: Variant
    gears: object  # tmm_cli.gears.design.GearsResult
    cam: object  # tmm_cli.cam.design.CamResult

    @property
    def notes(self) -> tuple[Note, ...]:
        seen: list[Note] = []
        for note in tuple(self.gears.notes) + tuple(self.cam.notes):
            if note not in seen:
                seen.append(note)
        return tuple(sorted(seen, key=lambda n: n.level != "assumption"))


def run_project(
    variant: Variant,
    crank_rpm: float | None = None,
    torque_nm: float | None = None,
    step_deg: float = 10.0,
    ratio: tuple[int, int] | None = None,
    tolerance_pct: float = 5.0,
    planets: int | None = None,
    shift=None,
    a_w_mm: float | None = None,
    select: str = "accurate",
    cam_choice=None,
    stiffness: bool = False,
) -> ProjectResult:
    """Run sheet 4 (motor, ratios, planetary reducer, spur pair) and sheet 3 (cam) for a variant.

    `select`: the reducer rule ("accurate" or "smallest", :func:`~tmm_cli.gears.design.design_gears`);
    `cam_choice`: the student's cam overrides (:class:`~tmm_cli.cam.design.CamChoice`) or None;
    `stiffness` adds the spur pair's mesh stiffness (beyond the course, ``--stiffness``)."""
    from .cam.design import design_cam
    from .gears.design import design_gears

    gears = design_gears(
        variant.n_cam_rpm,
        crank_rpm=crank_rpm,
        torque_nm=torque_nm,
        ratio=ratio,
        tolerance_pct=tolerance_pct,
        planets=planets,
        shift=shift,
        a_w_mm=a_w_mm,
        select=select,
        stiffness=stiffness,
    )
    cam = design_cam(variant, step_deg=step_deg, choice=cam_choice)
    return ProjectResult(variant=variant, gears=gears, cam=cam)
