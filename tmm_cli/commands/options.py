"""What the commands share: the context settings, the options, the reading of their values, and the
limits set on them (docs/limits.md).

Only click is imported here: ``tmm --help`` stays instant. The core is imported inside the helpers
that need it.
"""

from __future__ import annotations

import math
from pathlib import Path

import click

from ..limits import (
    CARRIER_RADIUS_MM,
    CARRIER_TOL_UM,
    CHAIN_RISK_PCT,
    CRANK_RPM,
    JOBS,
    MODULE_MM,
    PLANETARY_FAMILY,
    PLANETARY_Z,
    PLANETS,
    RTOL_PCT,
    SHIFT_X,
    STEP_DEG,
    TOLERANCE_PCT,
    TORQUE_NM,
)

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


def resolve_lang(lang: str | None) -> str:
    """--lang of the command, else --lang given before it (`tmm --lang ru cam …`), else the locale."""
    if lang:
        return lang
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.find_root().params.get("lang"):
        return ctx.find_root().params["lang"]
    from ..i18n.lang import default_lang

    return default_lang()


def variant_row(number: str, variants_file: str | None):
    from ..variants import get_variant

    return get_variant(number, variants_file)


def variant_folder(out: str | None, number: int) -> Path:
    base = Path(out) if out else Path("tmm-out")
    return base / f"variant-{number:02d}"


# Shared options --------------------------------------------------------------------------------

variant_option = click.option("--variant", "-v", "variant", required=True, metavar="N", help="Variant number from Table 1.2 (1–68).")
variants_file_option = click.option(
    "--variants-file", type=click.Path(dir_okay=False), default=None, metavar="PATH",
    help="Use your own table in the format of variants/table_1_2.csv.",
)
out_option = click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Output folder (default ./tmm-out); files go to DIR/variant-NN/.")
format_option = click.option("--format", "fmt", type=click.Choice(["png", "svg", "pdf"]), default="png", show_default=True, help="Figure file format.")
no_plots_option = click.option("--no-plots", is_flag=True, help="Do not draw figures (faster).")
sheets_option = click.option("--sheets", is_flag=True, help="Also write the A1 drawing sheet (DXF and PDF, ESKD frame and title block).")
force_option = click.option("--force", is_flag=True, help="Replace the files you changed since tmm wrote them (each kept as NAME.bak first).")
json_option = click.option("--json", "as_json", is_flag=True, help="Print only JSON on stdout.")
lang_option = click.option("--lang", type=click.Choice(["ru", "en"]), default=None, help="Output language (default: from the locale).")
step_option = click.option("--step", "step_deg", type=float, default=10.0, show_default=True, metavar="DEG", help="Cam angle step of the printed tables [deg].")
crank_option = click.option("--crank-rpm", type=float, default=None, metavar="R", help="Crank speed of the linkage n_кр [rpm] (default: the book's 220 rpm, stated in the output).")
mechanism_option = click.option("--mechanism", "mechanism_file", type=click.Path(dir_okay=False), default=None,
                                metavar="MECH.toml", help="The lever mechanism's file (docs/mechanism.md): sheet 4 takes "
                                "its driving moment and crank speed (sheets 1–2), instead of --torque and --crank-rpm.")
torque_option = click.option("--torque", "torque_nm", type=float, default=None, metavar="NM", help="Mean reduced moment M from sheet 2 [N·m], for the motor power (§2.6).")
ratio_option = click.option("--ratio", default=None, metavar="P/Q", help="Force the planetary ratio fraction of the book's procedure, e.g. 13/4.")
tolerance_option = click.option("--tolerance", "tolerance_pct", type=float, default=5.0, show_default=True, metavar="PCT", help="Allowed planetary ratio error [%].")
planets_option = click.option("--planets", type=int, default=None, metavar="K", help="Force the number of planets.")
shift_option = click.option("--shift", "shift", default=None, metavar="X1,X2|auto", help="Profile shifts of the spur pair (beyond the book), e.g. 0.3,-0.3; auto: no undercut, then a balanced split.")
aw_option = click.option("--aw", "a_w_mm", type=float, default=None, metavar="MM", help="Required centre distance of the spur pair a_w [mm]: x1 + x2 from it, split as auto.")


def shift_value(shift: str | None):
    if shift is None:
        return None
    from ..gears.shifted import parse_shift

    return parse_shift(shift)


select_option = click.option("--select", "select", type=click.Choice(["accurate", "smallest"]), default="accurate", show_default=True,
                             help="Which reducer to carry: the most accurate ratio among sets at most one tooth larger than the smallest, or the smallest.")


def gear_design_options(f):
    """The options of sheet 4's design that `tmm gears` and `tmm project` share, in their --help order."""
    for option in reversed((ratio_option, tolerance_option, planets_option, shift_option, aw_option, select_option,
                            stiffness_option)):
        f = option(f)
    return f


def cam_choice_options(f):
    """The student's say over the cam (issue 8): --r0, --offset, --l-oc, --swing, --roller."""
    for args, kw in reversed((
        (("--r0", "cam_r0"), dict(type=float, metavar="MM", help="Your base radius r0 of the pitch curve [mm] (checked, not replaced).")),
        (("--offset", "cam_offset"), dict(type=float, metavar="MM", help="Your offset e of a translating follower [mm] (e > 0: axis right of the cam centre).")),
        (("--l-oc", "cam_l_oc"), dict(type=float, metavar="MM", help="Your distance l_OC from the cam centre to the rocker pivot [mm].")),
        (("--swing", "cam_swing"), dict(type=click.Choice(["same", "opposite"]), help="Rocker turns on the rise the same way as the cam or opposite.")),
        (("--roller", "cam_roller"), dict(type=float, metavar="MM", help="Your roller radius [mm] (default: 0.2·r0, at most 0.8·ρ_min).")),
    )):
        f = click.option(*args, default=None, **kw)(f)
    return f


def cam_choice(kw: dict):
    from ..cam.design import CamChoice

    c = CamChoice(kw.pop("cam_r0", None), kw.pop("cam_offset", None), kw.pop("cam_l_oc", None),
                  kw.pop("cam_swing", None), kw.pop("cam_roller", None))
    return c if c.given else None


stiffness_option = click.option("--stiffness", is_flag=True, help="Also compute the spur pair's mesh stiffness (beyond the course, informative; V. P. Tarasik's method).")


def title_options(f):
    """--student, --group, --teacher, --org, --city, --designation: the title block and the note's title page."""
    helps = {
        "student": ("TEXT", "Student's name for the title block and the note, e.g. \"Иванов И. И.\" (or in tmm.toml)."),
        "group": ("TEXT", "Student's group (or in tmm.toml)."),
        "teacher": ("TEXT", "Teacher's name (or in tmm.toml)."),
        "org": ("TEXT", "University and department (or in tmm.toml)."),
        "city": ("TEXT", "City on the note's title page, above the year (or in tmm.toml)."),
        "designation": ("TEXT", "Drawing designation (default: built from the sheet and variant numbers)."),
    }
    for name, (metavar, text) in reversed(helps.items()):
        f = click.option(f"--{name}", f"title_{name}", default=None, metavar=metavar, help=text)(f)
    return f


def title_block(kwargs: dict):
    """Pop the title_* options out of a command's kwargs and merge them with tmm.toml."""
    from ..inputs.titleblock import title_fields

    given = {k[len("title_"):]: kwargs.pop(k) for k in list(kwargs) if k.startswith("title_")}
    return title_fields(given)


def ratio_value(ratio: str | None):
    if ratio is None:
        return None
    from ..gears.design import parse_ratio

    return parse_ratio(ratio)


# Limits on every number a user gives (docs/limits.md): ranges set on the options by name --------

def parse_decimal(text: str) -> float:
    """A number as people type it: a decimal dot or a decimal comma (``48,5``), spaces around.

    ValueError when it is not a number.

    >>> parse_decimal(" 48,5 "), parse_decimal("-0.25"), parse_decimal("1e3")
    (48.5, -0.25, 1000.0)
    """
    text = str(text).strip()
    if text.count(",") == 1 and "." not in text:
        text = text.replace(",", ".")
    return float(text)


class Range(click.ParamType):
    """A click type: a finite number, within [lo, hi] when they are given (a whole number when
    `integer`), typed with a decimal dot or a decimal comma (``--r0 48,5``).

    Every numeric option of every command has this type (:func:`apply_option_limits`), so all
    of them read numbers alike. Unlike click.FloatRange it refuses nan and inf, and an integer
    too large for a float.
    """

    name = "number"

    def __init__(self, lo=None, hi=None, integer: bool = False):
        self.lo, self.hi, self.integer = lo, hi, integer

    def _bounded(self) -> bool:
        return self.lo is not None and self.hi is not None

    def convert(self, value, param, ctx):
        if value is None:
            return None
        if self.integer:
            try:
                x = value if isinstance(value, int) and not isinstance(value, bool) else int(str(value).strip())
            except ValueError:
                if not self._bounded():
                    self.fail(f"'{str(value)[:30]}' is not a whole number; give one such as 3", param, ctx)
                self.fail(f"'{str(value)[:30]}' is not a whole number; give one from {self.lo} to {self.hi}", param, ctx)
            if self._bounded() and not self.lo <= x <= self.hi:
                shown = str(x) if abs(x) < 10**15 else f"a {len(str(abs(x)))}-digit number"
                self.fail(f"{shown} is out of range; give a whole number from {self.lo} to {self.hi} (docs/limits.md)", param, ctx)
            return x
        try:
            x = parse_decimal(value) if not isinstance(value, (int, float)) else float(value)
        except (ValueError, OverflowError):
            if not self._bounded():
                self.fail(f"'{str(value)[:30]}' is not a number; write it with a dot or a comma, e.g. 48.5 or 48,5", param, ctx)
            self.fail(f"'{str(value)[:30]}' is not a number; give one from {self.lo:g} to {self.hi:g}", param, ctx)
        if not math.isfinite(x):
            if not self._bounded():
                self.fail(f"'{str(value)[:30]}' is not a finite number; give an ordinary number such as 48,5", param, ctx)
            self.fail(f"{str(value)[:30]} is out of range; give a number from {self.lo:g} to {self.hi:g} (docs/limits.md)", param, ctx)
        if self._bounded() and not self.lo <= x <= self.hi:
            self.fail(f"{x:g} is out of range; give a number from {self.lo:g} to {self.hi:g} (docs/limits.md)", param, ctx)
        return x


OPTION_LIMITS = {
    "crank_rpm": Range(*CRANK_RPM),
    "torque_nm": Range(*TORQUE_NM),
    "tolerance_pct": Range(*TOLERANCE_PCT),
    "step_deg": Range(*STEP_DEG),
    "planets": Range(*PLANETS, integer=True),
    "rtol_pct": Range(*RTOL_PCT),
    "jobs": Range(*JOBS, integer=True),
    "radius_mm": Range(*CARRIER_RADIUS_MM),
    "tol_radial_um": Range(*CARRIER_TOL_UM),
    "tol_tangential_um": Range(*CARRIER_TOL_UM),
    "risk_pct": Range(*CHAIN_RISK_PCT),
    # tmm planetary
    "module_mm": Range(*MODULE_MM),
    "x1": Range(*SHIFT_X),
    "x2": Range(*SHIFT_X),
    "z_min": Range(*PLANETARY_Z, integer=True),
    "z_max": Range(*PLANETARY_Z, integer=True),
    "multiple": Range(*PLANETARY_FAMILY, integer=True),
}


def apply_option_limits(command) -> None:
    """Give every option of `command` (and its sub-commands) named in OPTION_LIMITS its range, and
    every other numeric option the same reading of numbers (a decimal comma, no nan or inf)."""
    for p in getattr(command, "params", ()):
        if isinstance(p, click.Option) and p.name in OPTION_LIMITS:
            p.type = OPTION_LIMITS[p.name]
        elif isinstance(p, click.Option) and isinstance(p.type, (click.types.FloatParamType, click.types.IntParamType)) \
                and not p.is_flag and p.nargs == 1:
            p.type = Range(integer=isinstance(p.type, click.types.IntParamType))  # a decimal comma everywhere
    for sub in getattr(command, "commands", {}).values():
        apply_option_limits(sub)
