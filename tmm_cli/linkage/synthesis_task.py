"""The task file of `tmm synth TASK.toml` (a dict from tomllib) → a checked :class:`Task`, and the
synthesis it asks for.

    type = "crank-rocker"           # crank-slider | crank-rocker | slotted-link
    name = "Механизм качающегося конвейера"
    rocker = 0.20                   # l_CD [m]
    swing_deg = 40                  # ψ
    time_ratio = 1.2                # K
    min_transmission_deg = 40       # γ (or frame = 0.30, l_AD [m])
    rpm = 120                       # optional: rpm or omega, sense, start_deg, positions, gravity, plan
    [[mass]] …                      # optional: the sheet-2 tables point, mass, load, dynamics (copied)

crank-slider: ``stroke`` H [m] with ``lambda`` (central), or ``time_ratio`` with ``offset`` e [m], or
``lambda`` with ``offset``. slotted-link: ``stroke``, ``time_ratio``, ``frame`` l_O1O2 [m],
optional ``rod_ratio`` (l_BC/l_O2B). Errors: one :class:`TmmError` line naming the key.
"""

from __future__ import annotations

import math

from ..errors import TmmError
from ..records import record
from .mechanism_file import RPM_MAX, _Reader
from .synthesis import (
    ROD_RATIO,
    TYPES,
    crank_rocker,
    crank_slider_central,
    crank_slider_lambda_offset,
    crank_slider_offset,
    slotted_link,
)

COMMON = ("type", "name", "positions", "rpm", "omega", "sense", "start_deg", "gravity", "plan", "point", "mass",
          "load", "dynamics")
KEYS = {
    "crank-slider": ("stroke", "lambda", "time_ratio", "offset"),
    "crank-rocker": ("rocker", "swing_deg", "time_ratio", "frame", "min_transmission_deg"),
    "slotted-link": ("stroke", "time_ratio", "frame", "rod_ratio"),
}
EXAMPLES = {"stroke": "stroke = 0.12", "lambda": "lambda = 0.25", "time_ratio": "time_ratio = 1.2",
            "offset": "offset = 0.02", "rocker": "rocker = 0.20", "swing_deg": "swing_deg = 40",
            "frame": "frame = 0.30", "min_transmission_deg": "min_transmission_deg = 40", "rod_ratio": "rod_ratio = 0.3",
            "type": 'type = "crank-rocker"'}


@record(eq=False)
class Task:
    """A synthesis task as read: its type, its numbers (SI), the optional keys copied to the file."""

    type: str
    name: str
    values: dict  # key → number, as the task gives them (degrees for *_deg)
    rpm: float | None
    omega: float | None
    sense: str
    start_deg: float | None
    positions: int
    gravity: bool | None
    plan: object
    tables: dict  # 'point', 'mass', 'load', 'dynamics' as read (checked by tmm linkage's parser)

    @property
    def record(self) -> dict:
        """The task as the mechanism file's [synthesis] table records it."""
        return {"type": self.type, **self.values}


def parse_task(data: dict, source: str = "task") -> Task:
    """Check a task read by tomllib.

    >>> t = parse_task({"type": "crank-slider", "stroke": 0.12, "lambda": 0.25, "rpm": 1450})
    >>> t.type, t.values, t.rpm, t.sense
    ('crank-slider', {'stroke': 0.12, 'lambda': 0.25}, 1450.0, 'ccw')
    >>> parse_task({"type": "crank-rocker", "rocker": 0.2, "swing_deg": 40, "time_ratio": 1.2}, "t.toml")
    Traceback (most recent call last):
    ...
    tmm_cli.errors.TmmError: t.toml: a crank-rocker task needs 'frame' (l_AD [m]) or 'min_transmission_deg' (γ), e.g. frame = 0.30
    """
    r = _Reader(source)
    if not isinstance(data, dict):
        r.fail("the file must hold TOML tables")
    kind = r.choice(r.required(data, "type", "type", EXAMPLES["type"]), "type", TYPES, EXAMPLES["type"])
    allowed = COMMON + KEYS[kind]
    for k in data:
        if k not in allowed:
            r.fail(f"unknown key '{k}'; known keys here: {', '.join(allowed)}")
    values = {}
    for k in KEYS[kind]:
        if k not in data:
            continue
        if k in ("stroke", "rocker", "frame"):
            values[k] = r.length(data[k], k, EXAMPLES[k])
        elif k == "offset":
            x = r.number(data[k], k, EXAMPLES[k])
            if not 0.0 <= x <= 100.0:
                r.fail(f"'offset' is {x:g}; the offset e must lie in [0, 100] m (the side is chosen by the working stroke)")
            values[k] = x
        else:
            values[k] = r.number(data[k], k, EXAMPLES[k])
    need = {"crank-rocker": ("rocker", "swing_deg", "time_ratio"), "slotted-link": ("stroke", "time_ratio", "frame"),
            "crank-slider": ("stroke",)}[kind]
    for k in need:
        r.required(values, k, k, EXAMPLES[k])
    if kind == "crank-slider" and "lambda" not in values and not ("time_ratio" in values and "offset" in values):
        r.fail("a crank-slider task gives lambda (central, or with offset) or time_ratio with offset, e.g. lambda = 0.25")
    if kind == "crank-slider" and "lambda" in values and "time_ratio" in values:
        r.fail("a crank-slider task gives lambda or time_ratio, not both (with lambda and offset K follows)")
    if kind == "crank-rocker" and "frame" not in values and "min_transmission_deg" not in values:
        r.fail("a crank-rocker task needs 'frame' (l_AD [m]) or 'min_transmission_deg' (γ), e.g. frame = 0.30")
    if "min_transmission_deg" in values and not 0.0 < values["min_transmission_deg"] < 90.0:
        r.fail(f"'min_transmission_deg' is {values['min_transmission_deg']:g}; the transmission angle γ must lie in "
               "(0, 90)° (usually at least 40°)")
    name = r.text(data.get("name", ""), "name", 'name = "Механизм"')[:200]
    positions = data.get("positions", 12)
    if isinstance(positions, bool) or not isinstance(positions, int) or not 2 <= positions <= 360:
        r.fail(f"'positions' is {positions!r}; give a whole number of crank positions from 2 to 360, e.g. positions = 12")
    rpm = omega = None
    if "rpm" in data and "omega" in data:
        r.fail("give the crank's speed once: 'rpm' or 'omega', not both")
    if "rpm" in data:
        rpm = r.number(data["rpm"], "rpm", "rpm = 60")
        if not 0.0 < rpm <= RPM_MAX:
            r.fail(f"'rpm' is {rpm:g}; the mean speed must lie in (0, {RPM_MAX:g}] rpm (the sense is 'sense')")
    if "omega" in data:
        omega = r.number(data["omega"], "omega", "omega = 6.28")
        if not 0.0 < omega <= RPM_MAX * math.pi / 30.0:
            r.fail(f"'omega' is {omega:g}; the mean speed must lie in (0, {RPM_MAX * math.pi / 30.0:.6g}] rad/s "
                   "(the sense is 'sense')")
    default_sense = "cw" if kind == "slotted-link" else "ccw"
    sense = r.choice(data.get("sense", default_sense), "sense", ("ccw", "cw"), 'sense = "ccw"')
    start = r.number(data["start_deg"], "start_deg", "start_deg = 90") if "start_deg" in data else None
    gravity = data.get("gravity")
    tables = {k: data[k] for k in ("point", "mass", "load", "dynamics") if k in data}
    return Task(kind, name, values, rpm, omega, sense, start, positions, gravity, data.get("plan"), tables)


def synthesise(task: Task, source: str = "task"):
    """The synthesis the task asks for: a SliderSynthesis, RockerSynthesis or SlottedSynthesis
    (an infeasible task: one TmmError line that starts with `source` and names the key)."""
    try:
        return _synthesise(task)
    except TmmError as exc:
        raise TmmError(f"{source}: {exc}") from None


def _synthesise(task: Task):
    v = task.values
    if task.type == "crank-slider":
        if "time_ratio" in v:
            return crank_slider_offset(v["stroke"], v["time_ratio"], v["offset"])
        if v.get("offset", 0.0) > 0.0:
            return crank_slider_lambda_offset(v["stroke"], v["lambda"], v["offset"])
        return crank_slider_central(v["stroke"], v["lambda"])
    if task.type == "crank-rocker":
        gamma = v.get("min_transmission_deg")
        return crank_rocker(v["rocker"], math.radians(v["swing_deg"]), v["time_ratio"], v.get("frame"),
                            None if gamma is None else math.radians(gamma))
    return slotted_link(v["stroke"], v["time_ratio"], v["frame"], v.get("rod_ratio", ROD_RATIO))
