"""The sheet-2 tables of a mechanism file → checked records: ``gravity``, ``[[mass]]``, ``[load]``,
``[dynamics]``.

Sheet 1 keeps these tables unread in ``Mechanism.extra`` (:mod:`.mechanism_file`); this module
checks them against the mechanism (the links they name must exist) and words its errors with the
same reader, one line naming the key as a path (``mass[2].m``, ``load.force``, ``dynamics.delta``)::

    gravity = true              # the links' weights m·g, g = 9.81 m/s² towards −y
    [dynamics]
    delta = 0.04                # the allowed coefficient of speed fluctuation δ, 0 < δ ≤ 0.5
    J_rotor = 0.0               # [kg·m²] of everything turning with the crank (the motor's rotor,
                                # the gears), reduced to the crank
    flywheel = "disc"           # the flywheel's form: "disc" (a solid disc) | "rim" (a rim, обод)
    width_ratio = 0.2           # ψ_b = b/D, its width over its (mean) diameter
    rim_ratio = 1.0             # ψ_h = h/b, a rim's thickness over its width
    density = 7800              # [kg/m³], steel
"""

from __future__ import annotations

from ..records import record
from .loads import Load, parse_load
from .masses import Mass, parse_masses
from .mechanism import Mechanism
from .mechanism_file import _Reader

DYNAMICS_KEYS = ("delta", "J_rotor", "flywheel", "width_ratio", "rim_ratio", "density")
DELTA_MAX = 0.5
DELTA_MIN = 1.0e-4  # below it the flywheel is no machine's (and the speed's bounds merge in rounding)
FLYWHEELS = ("disc", "rim")
STEEL = 7800.0  # [kg/m³]


@record
class DynamicsSpec:
    """The ``[dynamics]`` table: what the flywheel must achieve and its form."""

    delta: float  # δ = (ω_max − ω_min)/ω_m
    J_rotor: float  # [kg·m²] reduced to the crank
    flywheel: str  # 'disc' | 'rim'
    width_ratio: float  # ψ_b = b/D
    rim_ratio: float  # ψ_h = h/b (a rim)
    density: float  # [kg/m³]


@record
class Sheet2Input:
    """Everything sheet 2 reads from the file beyond the mechanism."""

    gravity: bool
    masses: tuple[Mass, ...]
    load: Load | None
    dynamics: DynamicsSpec | None
    gas: tuple = ()  # GasLoad: the gas forces from indicator diagrams ([[load]] with head)
    loads: tuple[Load, ...] = ()  # every table load (stroke/force or moment), in file order; `load` is the one on
    # the output link (None when none is)

    @property
    def tables(self) -> tuple[Load, ...]:
        """Every table load: `loads`, or `load` alone when `loads` is not given."""
        return self.loads or ((self.load,) if self.load is not None else ())

    @property
    def has_forces(self) -> bool:
        """The file asks for sheet 2: it gives masses or a load."""
        return bool(self.masses) or bool(self.tables) or bool(self.gas)

    @property
    def has_load(self) -> bool:
        """The file gives a useful resistance or a gas force: work for the motor to balance."""
        return bool(self.tables) or bool(self.gas)


def _ratio(r, t: dict, key: str, default: float, lo: float, hi: float) -> float:
    x = r.number(t.get(key, default), f"dynamics.{key}", f"{key} = {default:g}")
    if not lo < x <= hi:
        r.fail(f"'dynamics.{key}' is {x:g}; it must lie in ({lo:g}, {hi:g}]")
    return x


def parse_dynamics(r, raw) -> DynamicsSpec | None:
    """The ``[dynamics]`` table (None without one)."""
    if raw is None:
        return None
    t = r.table(raw, "dynamics", DYNAMICS_KEYS)
    delta = r.number(r.required(t, "delta", "dynamics.delta", "delta = 0.04"), "dynamics.delta", "delta = 0.04")
    if not 0.0 < delta <= DELTA_MAX:
        r.fail(f"'dynamics.delta' is {delta:g}; the coefficient of speed fluctuation δ must lie in (0, {DELTA_MAX:g}] "
               "(machines: 0.002 … 0.2), e.g. delta = 0.04")
    if delta < DELTA_MIN:
        r.fail(f"'dynamics.delta' is {delta:g}, below {DELTA_MIN:g}: no machine keeps its speed that steady (machines: "
               "0.002 … 0.2); give e.g. delta = 0.04")
    rotor = r.number(t.get("J_rotor", 0.0), "dynamics.J_rotor", "J_rotor = 0.05")
    if not 0.0 <= rotor <= 1.0e5:
        r.fail(f"'dynamics.J_rotor' is {rotor:g}; a moment of inertia must lie in [0, 100000] kg·m²")
    form = r.choice(t.get("flywheel", "disc"), "dynamics.flywheel", FLYWHEELS, 'flywheel = "disc"')
    width = _ratio(r, t, "width_ratio", 0.2, 0.0, 2.0)
    rim = _ratio(r, t, "rim_ratio", 1.0, 0.0, 10.0)
    density = _ratio(r, t, "density", STEEL, 0.0, 25000.0)
    return DynamicsSpec(delta, rotor, form, width, rim, density)


def parse_sheet2(mech: Mechanism, source: str = "mechanism") -> Sheet2Input:
    """Check the sheet-2 tables kept in ``mech.extra`` and return them as records.

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0]}, "crank": {"pivot": "O", "joint": "A",
    ...     "length": 0.06, "rpm": 1500}, "group": [{"kind": "RRP", "joints": ["A", "B"],
    ...     "length": 0.25, "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}],
    ...     "mass": [{"joint": "B", "m": -1.0}]})
    >>> parse_sheet2(m, "m.toml")
    Traceback (most recent call last):
    ...
    tmm_cli.errors.TmmError: m.toml: 'mass[1].m' is -1; a mass must lie in [0, 100000] kg
    """
    r = _Reader(source)
    extra = mech.extra
    gravity = extra.get("gravity", False)
    if not isinstance(gravity, bool):
        r.fail(f"'gravity' is {gravity!r}; write gravity = true (the links' weights count) or false")
    masses = parse_masses(r, mech, extra.get("mass"))
    raw = extra.get("load")
    gas = []
    loads: list[Load] = []
    if isinstance(raw, list):  # [[load]]: gas loads (with head) and table loads, each on its own link
        from .gas import parse_gas

        if not raw or len(raw) > 20:
            r.fail("'load' must be 1 to 20 tables [[load]]")
        tables = []
        for i, t in enumerate(raw, start=1):
            if isinstance(t, dict) and "head" in t:
                gas.append(parse_gas(r, mech, t, f"load[{i}]"))
            else:
                tables.append((i, t))
        if len({g.link for g in gas}) != len(gas):
            r.fail("'load': two gas loads on one piston; give each piston one [[load]]")
        if len(tables) == 1:  # one table load: on the output as ever (beside gas loads, on its own link)
            ld = parse_load(r, mech, tables[0][1], anywhere=bool(gas))
            loads = [ld] if ld is not None else []
        else:
            loads = _several(r, mech, tables, bool(gas))
        raw = None
    else:
        ld = parse_load(r, mech, raw)
        loads = [ld] if ld is not None else []
    load = next((ld for ld in loads if ld.link == mech.output.link), None)
    return Sheet2Input(gravity, masses, load, parse_dynamics(r, extra.get("dynamics")), tuple(gas), tuple(loads))


def _several(r, mech: Mechanism, tables, gas: bool) -> list[Load]:
    """Several table loads of [[load]], each on its own link (``load[i]`` in messages): two on one
    link are refused (one diagram per link: add them into one), and without gas loads one of them must
    be on the output link (position 0, the stroke and K of sheet 1 follow it)."""
    loads, seen = [], {}
    for i, t in tables:
        ld = parse_load(r, mech, t, f"load[{i}]", anywhere=True)
        if ld is None:
            r.fail(f"'load[{i}]' gives no load (only 'working'); give on, stroke and force (or moment), or drop it")
        if ld.link in seen:
            r.fail(f"'load[{i}].on' is the link {ld.link}, which load[{seen[ld.link]}] loads already: give each link "
                   "one table (add the two diagrams into one)")
        seen[ld.link] = i
        loads.append(ld)
    if not gas and mech.output.link not in seen:
        from .loads import _output_key

        first = mech.link(loads[0].link)
        r.fail(f"'output' is {mech.output.link}, which none of the table loads is on: position 0, the stroke and K "
               f"follow the output's working stroke; put output = {_output_key(first)} (or another loaded link) at "
               "the top of the file")
    return loads
