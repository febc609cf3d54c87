"""The structural analysis as the textbook writes it: Chebyshev's formula, the Assur groups with
their class, order and kind, the kinematic pairs, the structural formula.

Standard TMM (Artobolevsky; Frolov; Pozhbelko, part 1; METHOD.md "Sheets 1 and 2"): the degrees
of freedom of a planar mechanism W = 3n − 2p5 − p4 (n moving links, p5 lower pairs of class 5,
p4 higher pairs of class 4). The crank with the frame is the class I mechanism I(0,1); each dyad
is a group of class II, order 2, of kind 1 (RRR), 2 (RRP), 3 (RPR), 4 (PRP) or 5 (RPP). The
structural formula lists them in the order of attachment: I(0,1) → II(2,3) → II(4,5). The
mechanism's class is the highest class of its groups.
"""

from __future__ import annotations

from ..records import record
from .mechanism import Mechanism, Pair

KIND_NUMBER = {"RRR": 1, "RRP": 2, "RPR": 3, "PRP": 4, "RPP": 5}  # Artobolevsky: ВВВ, ВВП, ВПВ, ПВП, ВПП
ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV"}


@record
class StructuralGroup:
    """One member of the structural formula (the class I mechanism or an Assur group)."""

    index: int  # 0: the crank with the frame; 1, 2, …: the groups
    klass: int  # 1 | 2
    order: int | None  # 2 for a dyad; None for the class I mechanism
    kind: int | None  # 1 … 5 for a dyad
    pattern: str | None  # 'RRR', 'RRP', 'RPR' (None for the class I mechanism)
    links: tuple[int, ...]  # (0, 1) for the class I mechanism; (2k, 2k + 1) for group k
    pairs: tuple[Pair, ...]

    @property
    def formula(self) -> str:
        """'I(0,1)' or 'II(2,3)'."""
        return f"{ROMAN[self.klass]}({','.join(str(n) for n in self.links)})"


@record
class Structure:
    n: int  # moving links
    p5: int  # lower pairs (class 5)
    p4: int  # higher pairs (class 4)
    dof: int  # W = 3n − 2p5 − p4
    groups: tuple[StructuralGroup, ...]
    mechanism_class: int

    @property
    def formula(self) -> str:
        """'I(0,1) → II(2,3) → II(4,5)'."""
        return " → ".join(g.formula for g in self.groups)


def chebyshev(n: int, p5: int, p4: int = 0) -> int:
    """Degrees of freedom of a planar mechanism, W = 3n − 2p5 − p4 (Chebyshev's formula).

    >>> chebyshev(5, 7)   # the six-link shaping mechanism: 5 moving links, 7 lower pairs
    1
    """
    return 3 * n - 2 * p5 - p4


def structure(mech: Mechanism) -> Structure:
    """The structural analysis of the mechanism (its groups as the file builds them).

    >>> from .mechanism_file import parse_mechanism
    >>> m = parse_mechanism({"frame": {"O": [0, 0], "C": [0.3, 0]}, "crank": {"pivot": "O",
    ...     "joint": "A", "length": 0.1, "rpm": 60}, "group": [{"kind": "RRR",
    ...     "joints": ["A", "B", "C"], "lengths": [0.3, 0.2], "branch": "left"}]})
    >>> s = structure(m)
    >>> s.n, s.p5, s.dof, s.formula, s.groups[1].kind
    (3, 4, 1, 'I(0,1) → II(2,3)', 1)
    """
    n = len(mech.links)
    p5 = len(mech.pairs)
    crank_pairs = tuple(p for p in mech.pairs if p.group == 0)
    members = [StructuralGroup(0, 1, None, None, None, (0, 1), crank_pairs)]
    for g in mech.groups:
        members.append(StructuralGroup(g.index, 2, 2, KIND_NUMBER[g.kind], g.kind, g.numbers, g.pairs))
    return Structure(n, p5, 0, chebyshev(n, p5, 0), tuple(members), max(m.klass for m in members))
