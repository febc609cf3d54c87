"""A lever mechanism as the structural formula builds it: the frame, the crank, class II groups.

The standard TMM method (Artobolevsky; Frolov; Pozhbelko, part 1; /work/shared/METHOD.md, "Sheets
1 and 2"): a one-degree-of-freedom mechanism is the crank (a class I mechanism: the frame and the
input link) with Assur groups of class II (dyads) attached one after another, each to joints that
are already placed. Frame: x right, y up, metres; angles from +x counter-clockwise.

This module holds the description as frozen records, with the topology the later sheets need
(links and their numbers, kinematic pairs, which link each joint is fixed on). Links are numbered
as the book numbers them: 0 the frame, 1 the crank, then two per group in the formula's order:

==========  ====================  =======================================================
group kind  joints (file order)   links 2k, 2k+1 (k = group's index)
==========  ====================  =======================================================
RRR         A, B, C (B new)       bar AB, bar BC
RRP         A, B (B new, slider)  bar AB, slider B (a block on a fixed guide)
RPR         A, C (nothing new)    block A (turns on the pin A), slotted link AC (turns
                                  about C, the block slides along it; its slot may pass
                                  the offset d from C)
PRP         B (new)               block B′ on the guide G1, block B on the guide G2, hinged
                                  together at B (where the guides' lines cross)
RPP         A, Y (Y new)          block A (hinged at A, slides in the yoke's slot), yoke Y
                                  (slides along its guide; Y: where the slot crosses it)
==========  ====================  =======================================================

The angle of a link named XY is the direction from X to Y (the crank's: from its pivot to its
joint, the crank angle φ); a slider's angle is its guide's, a block's is its slotted link's.
Parsing (:func:`parse_mechanism`, in :mod:`.mechanism_file`) checks the form and the references;
whether every group can be assembled over the whole turn is checked by :mod:`.assembly`.
"""

from __future__ import annotations

import cmath
import math

from ..records import record

KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")
FRAME = 0  # the frame's link number


@record
class Guide:
    """A straight guide: fixed — the line through `through` in the direction `angle` — or on a
    moving link (`link`): the line through the link's point at `along`, `across` from its pin
    `base` towards `toward` (as a [[point]]), turned `angle` from the link's direction base →
    toward; it turns with the link (:func:`.chain.guide_frame` gives it at any crank angle)."""

    through: complex  # a point of the line [m] (a fixed guide)
    angle: float  # direction from +x, counter-clockwise [rad]; on a link: from the link's direction
    link: str | None = None  # the link carrying the guide (None: the frame)
    base: str = ""
    toward: str = ""
    along: float = 0.0  # [m]
    across: float = 0.0  # [m]

    @property
    def moving(self) -> bool:
        return self.link is not None

    @property
    def unit(self) -> complex:
        """A fixed guide's direction as a unit vector (complex x + iy)."""
        if self.link is not None:
            raise ValueError("a moving guide's direction changes with the crank angle: use chain.guide_frame")
        return cmath.exp(1j * self.angle)


@record
class Crank:
    """The input link: turns about the fixed `pivot`; its other end is the joint `joint`."""

    pivot: str
    joint: str
    length: float  # [m]
    omega: float  # mean angular velocity [rad/s], counter-clockwise positive (sign = sense)
    start: float | None  # crank angle of position 0 [rad]; None: the book's rule (positions.py)

    @property
    def sense(self) -> int:
        """+1 counter-clockwise, −1 clockwise."""
        return 1 if self.omega > 0 else -1

    @property
    def rpm(self) -> float:
        """|n| [rpm]."""
        return abs(self.omega) * 30.0 / math.pi


@record
class Pair:
    """A lower kinematic pair (class 5): a pin (R) or a slide (P) between two links."""

    joint: str  # where it is (a P pair: the joint of the block or slider on it)
    kind: str  # 'R' or 'P'
    links: tuple[int, int]  # link numbers, the earlier (or the frame, 0) first
    group: int  # 0: the crank's pair with the frame; k: group k's


@record
class Link:
    """A moving link."""

    name: str  # 'OA', 'AB' (bars: two joints in file order); 'B' (a slider or block: its joint)
    number: int  # 1 the crank, 2k and 2k+1 group k's
    kind: str  # 'crank' | 'bar' | 'slider' | 'block' | 'slotted'
    group: int  # 0 for the crank
    axis: tuple[str, str] | None  # its angle is the direction axis[0] → axis[1]; None: a slider
    pins: tuple[str, ...]  # joints fixed on the link (points of it whatever the position)


@record
class Group:
    """A class II Assur group (dyad) as the file gives it, with its place in the structure."""

    index: int  # 1, 2, … in the structural formula's order
    kind: str  # 'RRR' | 'RRP' | 'RPR'
    joints: tuple[str, ...]  # as in the file: RRR (A, B, C), RRP (A, B), RPR (A, C)
    lengths: tuple[float, ...]  # RRR (AB, BC), RRP (AB,), RPR () [m]
    branch: int  # RRR: +1 B left of A→C, −1 right; RRP: +1 ahead, −1 behind; RPR: 0
    guide: Guide | None  # RRP's fixed guide
    known: tuple[str, ...]  # the joints it hangs on (placed before it)
    new: tuple[str, ...]  # the joints it places: RRR, RRP (B,); RPR ()
    links: tuple[str, str]  # its two links' names, numbers 2k and 2k+1
    pairs: tuple[Pair, Pair, Pair]  # its three pairs, from the first known joint along the chain
    offset: float = 0.0  # RPR: the slot's distance d from the pivot C [m] (the slot is C + d·n + t·u)
    guides: tuple[Guide, ...] = ()  # PRP: (G1, G2), the guides of its blocks B′ and B
    slot: float = 0.0  # RPP: the yoke's slot from its guide's direction [rad]

    @property
    def numbers(self) -> tuple[int, int]:
        return 2 * self.index, 2 * self.index + 1

    @property
    def label(self) -> str:
        """'RRR A-B-C' (for messages)."""
        return f"{self.kind} {'-'.join(self.joints)}"


@record
class Point:
    """A named point fixed on a moving link (a centre of mass, or a joint a later group uses)."""

    name: str
    link: str  # the link's name
    base: str  # measured from this pin of the link …
    toward: str  # … towards this joint (the link's axis through base)
    along: float  # [m] from base towards `toward`
    across: float  # [m] to the left of that direction


@record
class Output:
    """The output link whose extreme positions define position 0, the stroke and K."""

    kind: str  # 'slider' (a displacement along its guide) or 'rocker' (an angle)
    link: str  # the link's name
    joint: str  # slider: its joint; rocker: the link's moving end (for 'away from the crank')
    group: int


@record
class Mechanism:
    """The validated description; lookups by name through the mappings below."""

    name: str
    positions: int  # evenly spaced crank positions per turn
    frame: dict[str, complex]  # fixed joints [m]
    crank: Crank
    groups: tuple[Group, ...]
    points: tuple[Point, ...]
    links: tuple[Link, ...]  # moving links by number: links[i].number == i + 1
    pairs: tuple[Pair, ...]  # the crank's, then three per group
    carrier: dict[str, int]  # joint or point → the number of the link it is a pin of (0: frame)
    output: Output
    working: str | None  # 'away' | 'towards' (from [load] working), else None
    plan: str | None  # label of the position of the plans (file key `plan`), else None
    extra: dict  # the sheet-2 tables as read ('gravity', 'mass', 'load', 'dynamics') and 'synthesis', unchecked
    gas_head: tuple[str, complex] | None = None  # the first [[load]]'s piston and head, if a gas load

    def link(self, name: str) -> Link:
        for ln in self.links:
            if ln.name == name:
                return ln
        raise KeyError(name)

    def guided(self) -> tuple[tuple[str, Guide], ...]:
        """Every slider or block that slides along a Guide, with it: an RRP's slider, a PRP's two
        blocks, an RPP's yoke (an RPP's block slides in the yoke's slot, not on a Guide)."""
        out = []
        for g in self.groups:
            if g.kind == "RRP":
                out.append((g.links[1], g.guide))
            elif g.kind == "PRP":
                out += [(g.links[0], g.guides[0]), (g.links[1], g.guides[1])]
            elif g.kind == "RPP":
                out.append((g.links[1], g.guide))
        return tuple(out)

    def slider_turns(self, name: str) -> bool:
        """Whether the slider or block link `name` turns (it rides on a moving guide or in a turning
        yoke); a slider on a fixed guide only translates."""
        ln = self.link(name)
        g = self.groups[ln.group - 1]
        if ln.kind == "block":
            return True
        if g.kind == "PRP":
            return g.guides[0 if ln.number == 2 * g.index else 1].moving
        return g.guide is not None and g.guide.moving

    def link_between(self, j1: str, j2: str) -> Link | None:
        """The moving link whose axis joins j1 and j2 (either order), or None."""
        for ln in self.links:
            if ln.axis is not None and set(ln.axis) == {j1, j2}:
                return ln
        return None

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Every joint and named point, in the order they are placed (frame first)."""
        names = list(self.frame) + [self.crank.joint]
        group_of = {ln.name: ln.group for ln in self.links}
        for k in range(len(self.groups) + 1):
            if k:
                names += self.groups[k - 1].new
            names += [pt.name for pt in self.points if group_of[pt.link] == k]
        return tuple(dict.fromkeys(names))

    @property
    def scale_m(self) -> float:
        """A size of the mechanism [m]: the largest length or frame coordinate (for tolerances)."""
        sizes = [self.crank.length, *(abs(z) for z in self.frame.values())]
        for g in self.groups:
            sizes += list(g.lengths) + [abs(g.offset)]
            for gd in ((g.guide,) if g.guide is not None else ()) + g.guides:
                sizes.append(abs(gd.through) + abs(complex(gd.along, gd.across)))
        sizes += [abs(complex(p.along, p.across)) for p in self.points]
        return max(sizes)
