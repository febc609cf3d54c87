"""A dimensional chain from TOML text (seed 003, second article; issue 23).

Seed 003, second article (Абдуллаев, Расулов, «Размерные цепи в многоступенчатых пакетных
редукторах»): the radial clearance of a mesh is the closing link of a chain of shaft radii,
clearances and wall thicknesses ((1)–(4)); the tooth-direction error is the closing link of an
angular chain of key-joint deviations ((5), (6)); a hub sitting on its shaft with the radial
clearance δ over the length l turns by β = arctg(δ/l).

The file::

    name = "Radial clearance, chain (1)"
    units = "mm"                 # or an angle: "deg", "arcmin", "arcsec", "rad", "mrad", "urad"
    [[link]]
    name = "A"                   # unique within the chain
    nominal = 125.0              # in `units`, not negative (the sign says the direction)
    es = 0.04                    # upper deviation
    ei = -0.04                   # lower deviation, not above es
    sign = "+"                   # "+" the link increases the closing link, "-" decreases it
    distribution = "normal"      # optional: normal (λ² = 1/9), triangle (1/6), uniform (1/3)
    asymmetry = 0.0              # optional: α, the centre of dispersion's shift in T/2, −1…1
    [[link]]                     # in an angular chain, a hub's clearance:
    name = "beta1"
    clearance = 0.02             # radial clearance δ [mm]
    length = 40.0                # length of the fit l [mm]
    sign = "+"                   # -> a link 0 ± arctg(δ/l)

The command reads the file; this module takes its text and returns a :class:`Chain` in SI units
(metres or radians), or raises :class:`~tmm_cli.errors.TmmError` naming the link and the key.

>>> chain = parse_chain('''
... name = "two links"
... [[link]]
... name = "A"
... nominal = 100
... es = 0.1
... ei = -0.1
... sign = "+"
... [[link]]
... name = "B"
... nominal = 40
... es = 0
... ei = -0.05
... sign = "-"
... ''')
>>> [(k.name, k.sign, round(k.nominal * 1e3, 9), round(k.ei * 1e3, 9)) for k in chain.links]
[('A', 1, 100.0, -0.1), ('B', -1, 40.0, -0.05)]
"""

from __future__ import annotations

import math

from ..errors import TmmError
from ..limits import CHAIN_BYTES, CHAIN_LINKS
from ..records import record

UNITS = {
    "mm": (1e-3, False), "um": (1e-6, False), "µm": (1e-6, False),
    "rad": (1.0, True), "mrad": (1e-3, True), "urad": (1e-6, True), "µrad": (1e-6, True),
    "deg": (math.pi / 180.0, True), "arcmin": (math.pi / 10800.0, True), "arcsec": (math.pi / 648000.0, True),
}
"""A chain's ``units``: the factor to SI (metres, radians) and whether the chain is angular."""

LAMBDA2 = {"normal": 1.0 / 9.0, "triangle": 1.0 / 6.0, "uniform": 1.0 / 3.0}
"""Relative dispersion λ² of a link's distribution (the issue: 1/9, 1/6, 1/3; the standard
probabilistic method of dimensional chains, e.g. ГОСТ 16320-80 / Солонин [3] of the article)."""

_TOP = ("name", "units", "link")
_LINK = ("name", "nominal", "es", "ei", "sign", "distribution", "asymmetry", "clearance", "length")


@record
class Link:
    """One link of a dimensional chain, SI units (metres or radians).

    ``clearance``/``length`` [m] are set for a hub's clearance turned into the angular link
    0 ± arctg(δ/l) (seed 003, second article); then ``nominal`` = 0 and es = −ei = β.
    """

    name: str
    nominal: float
    es: float
    ei: float
    sign: int  # +1 increasing, −1 decreasing (ξ)
    distribution: str
    lambda2: float
    asymmetry: float  # α
    clearance: float | None = None
    length: float | None = None

    @property
    def tolerance(self) -> float:
        """T = es − ei."""
        return self.es - self.ei

    @property
    def middle(self) -> float:
        """Middle deviation E_c = (es + ei)/2."""
        return 0.5 * (self.es + self.ei)


@record
class Chain:
    """A dimensional chain: its links and the unit its file used (``unit_si`` converts to SI)."""

    name: str
    units: str
    unit_si: float
    angular: bool
    links: tuple[Link, ...]


def clearance_angle(clearance: float, length: float) -> float:
    """β = arctg(δ/l) [rad]: how far a hub with the radial clearance δ over the length l turns on
    its shaft (seed 003, second article, the formula before Fig. 3; the OCR prints the length as t).

    >>> round(math.degrees(clearance_angle(0.02, 40.0)) * 60, 4)  # δ = 0.02 mm, l = 40 mm: in arcmin
    1.7189
    """
    return math.atan(clearance / length)


def _number(value, where: str, key: str, unit: str | None) -> float:
    """``value`` as a finite float; TmmError naming the link, the key and the unit (None: a pure number)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        if unit is None:
            raise TmmError(f"{where}: {key} is {value!r}; give a number")
        raise TmmError(f"{where}: {key} is {value!r}; give a number in {unit}")
    x = float(value)
    if not math.isfinite(x):
        if unit is None:
            raise TmmError(f"{where}: {key} is {value}; give a finite number")
        raise TmmError(f"{where}: {key} is {value}; give a finite number in {unit}")
    return x


def _link(table, index: int, chain_unit: str, factor: float, angular: bool, seen: set[str]) -> Link:
    where = f"link {index}"
    if not isinstance(table, dict):
        raise TmmError(f"{where} is not a table; write each link as [[link]] with name, nominal, es, ei, sign")
    for key in table:
        if key not in _LINK:
            raise TmmError(f"{where}: unknown key '{key}'; a link has {', '.join(_LINK)}")
    name = table.get("name")
    if not isinstance(name, str) or not name.strip():
        raise TmmError(f"{where} has no name; give each link a name, e.g. name = \"A\"")
    name = name.strip()
    if len(name) > 40:
        raise TmmError(f"{where}: the name is {len(name)} characters long; keep it under 40")
    where = f"link {index} ('{name}')"
    if name in seen:
        raise TmmError(f"{where}: the name is used twice; give each link its own name")
    seen.add(name)
    sign = table.get("sign")
    if sign not in ("+", "-"):
        raise TmmError(f"{where}: sign is {sign!r}; give \"+\" (the link increases the closing link) or \"-\" "
                       f"(it decreases it)")
    distribution = table.get("distribution", "normal")
    if distribution not in LAMBDA2:
        raise TmmError(f"{where}: distribution is {distribution!r}; give normal, triangle or uniform")
    asymmetry = _number(table.get("asymmetry", 0.0), where, "asymmetry", None)
    if not -1.0 <= asymmetry <= 1.0:
        raise TmmError(f"{where}: asymmetry is {asymmetry:g}; α shifts the centre of dispersion by α·T/2, "
                       f"give −1 to 1")
    common = dict(name=name, sign=1 if sign == "+" else -1, distribution=distribution,
                  lambda2=LAMBDA2[distribution], asymmetry=asymmetry)
    if "clearance" in table or "length" in table:
        if not angular:
            raise TmmError(f"{where}: clearance and length make an angular link β = arctg(δ/l); set the chain's "
                           f"units to an angle (deg, arcmin, arcsec, rad, mrad, urad)")
        for key in ("nominal", "es", "ei"):
            if key in table:
                raise TmmError(f"{where}: give either clearance and length or nominal, es and ei, not both")
        for key in ("clearance", "length"):
            if key not in table:
                raise TmmError(f"{where}: {key} is missing; a clearance link needs clearance and length in mm")
        delta = _number(table["clearance"], where, "clearance", "mm")
        length = _number(table["length"], where, "length", "mm")
        if delta <= 0 or length <= 0:
            raise TmmError(f"{where}: clearance {delta:g} mm, length {length:g} mm; both must be positive")
        if delta >= length:
            raise TmmError(f"{where}: the clearance {delta:g} mm is not smaller than the length {length:g} mm; "
                           f"give the radial clearance and the length of the fit in mm")
        beta = clearance_angle(delta, length)
        return Link(nominal=0.0, es=beta, ei=-beta, clearance=delta * 1e-3, length=length * 1e-3, **common)
    for key in ("nominal", "es", "ei"):
        if key not in table:
            raise TmmError(f"{where}: {key} is missing; a link needs nominal, es, ei (in {chain_unit}) and sign")
    nominal = _number(table["nominal"], where, "nominal", chain_unit)
    es = _number(table["es"], where, "es", chain_unit)
    ei = _number(table["ei"], where, "ei", chain_unit)
    if nominal < 0:
        raise TmmError(f"{where}: nominal is {nominal:g}; give its size (not negative) and say its direction "
                       f"with sign = \"-\"")
    if es < ei:
        raise TmmError(f"{where}: es = {es:g} is below ei = {ei:g}; es is the upper deviation, ei the lower")
    return Link(nominal=nominal * factor, es=es * factor, ei=ei * factor, **common)


def parse_chain(text: str, source: str = "chain") -> Chain:
    """The :class:`Chain` (SI) in TOML ``text``; ``source`` names it in errors (the module's text).

    >>> parse_chain('name = "x"')
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: chain has no links; add [[link]] tables with name, nominal, es, ei, sign
    """
    import tomllib

    if len(text.encode("utf-8", "surrogatepass")) > CHAIN_BYTES:
        raise TmmError(f"{source} is larger than {CHAIN_BYTES >> 10} KiB")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise TmmError(f"{source} is not valid TOML: {exc}") from None
    except (RecursionError, ValueError, MemoryError):  # nested thousands deep; an integer of thousands of digits
        raise TmmError(f"{source} is not valid TOML (too deeply nested or a number too long); write [[link]] tables "
                       f"with name, nominal, es, ei, sign") from None
    for key in data:
        if key not in _TOP:
            raise TmmError(f"{source}: unknown key '{key}'; a chain has name, units and [[link]] tables")
    name = data.get("name", "")
    if not isinstance(name, str):
        raise TmmError(f"{source}: name is {name!r}; give the chain's name as a string")
    units = data.get("units", "mm")
    if units not in UNITS:
        raise TmmError(f"{source}: units is {units!r}; give mm, um, or an angle: deg, arcmin, arcsec, rad, mrad, urad")
    factor, angular = UNITS[units]
    tables = data.get("link", [])
    if not isinstance(tables, list):
        raise TmmError(f"{source}: write the links as [[link]] tables, not [link]")
    if not tables:
        raise TmmError(f"{source} has no links; add [[link]] tables with name, nominal, es, ei, sign")
    if len(tables) > CHAIN_LINKS:
        raise TmmError(f"{source} has {len(tables)} links; a chain may have up to {CHAIN_LINKS}")
    seen: set[str] = set()
    links = tuple(_link(t, i, units, factor, angular, seen) for i, t in enumerate(tables, 1))
    return Chain(name=name.strip()[:200], units=units, unit_si=factor, angular=angular, links=links)
