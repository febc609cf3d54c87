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
    """Both sheets of one variant; `notes` gathers the notes of both, assumptions first.

    With a mechanism file (``tmm project --mechanism``), `linkage` holds its sheets 1 and 2
    (:class:`tmm_cli.linkage.sheet2.Sheet2`, whose ``sheet1`` is sheet 1) and `linkage_notes` says
    that sheet 4 took the driving moment and the crank's speed from it."""

    variant: Variant
    gears: object  # tmm_cli.gears.design.GearsResult
    cam: object  # tmm_cli.cam.design.CamResult
    linkage: object = None  # tmm_cli.linkage.sheet2.Sheet2, or None
    linkage_notes: tuple = ()

    @property
    def notes(self) -> tuple[Note, ...]:
        seen: list[Note] = []
        for note in tuple(self.linkage_notes) + tuple(self.gears.notes) + tuple(self.cam.notes):
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
    linkage=None,
    linkage_name: str = "",
) -> ProjectResult:
    """Run sheet 4 (motor, ratios, planetary reducer, spur pair) and sheet 3 (cam) for a variant.

    `select`: the reducer rule ("accurate" or "smallest", :func:`~tmm_cli.gears.design.design_gears`);
    `cam_choice`: the student's cam overrides (:class:`~tmm_cli.cam.design.CamChoice`) or None;
    `stiffness` adds the spur pair's mesh stiffness (beyond the course, ``--stiffness``);
    `linkage` (sheets 1–2 of a mechanism file, :func:`analyse_linkage`; `linkage_name` its file's
    name) gives sheet 4 its mean reduced moment M (the driving moment) and the crank's speed, in
    place of `torque_nm` and `crank_rpm`."""
    from .cam.design import design_cam
    from .gears.design import design_gears

    notes = ()
    if linkage is not None:
        torque_nm, crank_rpm = linkage.motor_input()
        notes = (Note.make("project_mechanism_motor", "assumption", torque=torque_nm, rpm=crank_rpm,
                           file=linkage_name),) + linkage_warnings(linkage)
        if linkage.is_engine:  # an engine: M is its consumer's resisting moment
            notes += (Note.make("project_engine_consumer", "assumption", torque=torque_nm),)

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
    return ProjectResult(variant=variant, gears=gears, cam=cam, linkage=linkage, linkage_notes=notes)


def linkage_warnings(s2) -> tuple[Note, ...]:
    """The warnings of sheets 1 and 2 (a pressure angle above the usual limit, K < 1, a negative driving
    moment …): a poor design is said in the project's terminal and results.json as well, not only in
    linkage.json (their assumptions stay there)."""
    return tuple(n for n in tuple(s2.sheet1.cycle.notes) + tuple(s2.notes) if n.level == "warning")


def analyse_linkage(tables: dict, source: str = "mechanism"):
    """Sheets 1 and 2 of a mechanism file's tables (as :func:`tmm_cli.inputs.mechanism.read_mechanism_tables`
    reads them): the :class:`~tmm_cli.linkage.sheet2.Sheet2` whose driving moment and crank speed
    sheet 4 takes. The file must give the load (sheet 4 needs the work the machine does)."""
    from .errors import TmmError
    from .linkage.mechanism_file import parse_mechanism
    from .linkage.sheet1 import analyse_mechanism
    from .linkage.sheet2 import analyse_sheet2
    from .linkage.sheet2_file import parse_sheet2

    mech = parse_mechanism(tables, source)
    inp = parse_sheet2(mech, source)
    if not inp.has_load:
        raise TmmError(f"{source} has no [load]: sheet 4 takes the motor's moment from the work of the useful "
                       "resistance; add the [load] table (docs/dynamics.md) or give --torque without --mechanism")
    return analyse_sheet2(analyse_mechanism(mech, source=source), inp, source)
