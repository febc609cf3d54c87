"""A student's planetary reducer, judged by the five conditions of §2.1.3 rather than by equality
with the reducer the program carries.

The book's hand procedure and the program's search may rightly give different tooth sets, and the
book takes any k that fits (its §2.4 example keeps k = 5 of the admissible 2, 5, 10, 13 …; a student
who fits k = 3 planets of 35/25/85 has a working reducer). A set that meets every condition with the
ratio within the tolerance is a *valid alternative*; the quantities derived from it (its ratio, its
ratio error) are then checked against that set. A set that breaks a condition is told which one.

Nothing here raises on a hostile set (z_k = z_n, z_c′ = 0, k = 0): a set that cannot be evaluated is
a set with a problem.
"""

from __future__ import annotations

from fractions import Fraction

from ..notes import Note
from ..records import record

# the answer keys of a stage: sun, planet, second planet row (scheme 2), ring, planets
STAGE_KEYS = (("z_sun", "z_planet", "z_planet2", "z_ring", "planets"), ("z_sun_2", "z_planet_2", None, "z_ring_2", "planets_2"))


@record
class StudentReducer:
    """The student's tooth set and planets, the conditions it breaks, and its ratio."""

    scheme: str
    stages: tuple  # of conditions.Stage
    problems: tuple  # Note objects: the conditions broken, in the book's order
    ratio: float | None  # i_kH of the whole reducer (None if a stage has a zero)
    ratio_error_pct: float | None
    k_max: tuple  # the largest k each stage admits (exact assembly and neighbouring)

    @property
    def valid(self) -> bool:
        return not self.problems

    @property
    def teeth_text(self) -> str:
        return " + ".join("/".join(str(z) for z in s.teeth) for s in self.stages)


def _whole(value) -> int | None:
    """A tooth count or a number of planets as a whole number, or None (not given, not whole)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    if isinstance(value, float):
        if not value.is_integer() or abs(value) > 10**6:
            return None
        return int(value)
    return value if abs(value) <= 10**6 else None


def student_reducer(answers: dict, scheme: str, target: float, tolerance_pct: float) -> StudentReducer | None:
    """The student's reducer from the answers (keys as :func:`~tmm_cli.teacher.keys.resolve_key`
    reads them), or None when it is incomplete (then it is compared number by number).

    The conditions (§2.1.3): the ratio within ±`tolerance_pct` of `target` (2.1); coaxiality;
    assembly for the given k, exact form (METHOD.md; the book's (2.4) for scheme 1); neighbouring
    (2.5); no interference (Table 2.2). The book's §2.4 set is valid with any k it admits:

    >>> r = student_reducer(dict(z_sun=40, z_planet=25, z_ring=90, planets=2), "1", 3.25, 5.0)
    >>> r.valid, round(r.ratio, 4), r.k_max
    (True, 3.25, (5,))
    >>> r = student_reducer(dict(z_sun=40, z_planet=25, z_ring=40, planets=3), "1", 3.25, 5.0)
    >>> [n.code for n in r.problems]
    ['set_ratio', 'set_coaxial', 'set_assembly', 'set_interference']
    >>> [n.code for n in student_reducer(dict(z_sun=400000, z_planet=250000, z_ring=900000, planets=2), "1", 3.25, 5.0).problems]
    ['set_too_large']
    """
    from ..gears.planetary.conditions import K_MAX, Stage
    from ..gears.planetary.search import Z_MAX

    n_stages = 2 if scheme == "1+1" else 1
    stages, problems = [], []
    for j, keys in enumerate(STAGE_KEYS[:n_stages], start=1):
        zs, zp, zp2, zn, kk = keys
        need = [zs, zp, zn, kk] + ([zp2] if scheme == "2" else [])
        values = {k: _whole(answers.get(k)) for k in need}
        if any(v is None for v in values.values()):
            return None
        stages.append(Stage(values[zs], values[zp], values.get(zp2) if scheme == "2" else None, values[zn], values[kk]))
        if any(v <= 0 for v in values.values()):
            problems.append(Note.make("set_not_positive"))
        elif any(values[k] > Z_MAX for k in need if k != kk) or values[kk] > K_MAX:
            # the bounds of the program's own search: the right set ×10 000 meets every condition
            problems.append(Note.make("set_too_large", z_max=Z_MAX, k_max=K_MAX))
    if problems:
        return StudentReducer(scheme, tuple(stages), tuple(problems), None, None, tuple(1 for _ in stages))
    ratio = 1.0
    for s in stages:
        ratio *= float(s.ratio_fraction)
    err = (ratio / target - 1.0) * 100.0
    if abs(err) > tolerance_pct * (1 + 1e-9) + 1e-9:
        problems.append(Note.make("set_ratio", ratio=round(ratio, 4), target=round(target, 4), err=round(err, 2),
                                  tol=float(tolerance_pct)))
    k_max = []
    for j, s in enumerate(stages, start=1):
        k_max.append(_stage_problems(s, j, n_stages, problems))
    order = ("set_ratio", "set_coaxial", "set_assembly", "set_neighbour", "set_interference")
    problems.sort(key=lambda n: order.index(n.code.removesuffix("_stage")) if n.code.removesuffix("_stage") in order
                  else len(order))
    return StudentReducer(scheme, tuple(stages), tuple(problems), ratio, err, tuple(k_max))


def _stage_problems(s, j: int, n_stages: int, problems: list) -> int:
    """Append the conditions 2–5 of §2.1.3 that stage `s` breaks; return the largest k it admits."""
    from ..gears.planetary.conditions import check_stage

    c = check_stage(s)
    sfx = "_stage" if n_stages > 1 else ""  # "stage 2: …" only where there are two
    if not c.coaxial_ok:
        lhs = "z_k + z_c"
        rhs = "z_n − z_c′" if s.z_planet2 is not None else "z_n − z_c"
        problems.append(Note.make("set_coaxial" + sfx, stage=j, lhs=c.coaxial_lhs, rhs=c.coaxial_rhs,
                                  formula=f"{lhs} = {rhs}"))
    if not c.assembly_exact_ok:
        problems.append(Note.make("set_assembly" + sfx, stage=j, k=s.planets,
                                  ks=", ".join(str(k) for k in c.assembly_ks_exact[:6]) or "—"))
    if not c.neighbour_ok:
        problems.append(Note.make("set_neighbour" + sfx, stage=j, k=s.planets, sin=round(c.neighbour_sin, 3),
                                  q=round(float(Fraction(c.neighbour_q).limit_denominator(10**6)), 3),
                                  limit=c.neighbour_limit))
    for item in c.interference:
        if not item.ok:
            problems.append(Note.make("set_interference" + sfx, stage=j, symbol=item.symbol, value=item.value,
                                      limit=item.limit))
            break
    return c.k_max
