"""The closing link of a dimensional chain: worst case and probabilistic (seed 003, second article).

Seed 003, second article (Абдуллаев, Расулов): the nominal of the closing link is the sum of the
links with their directions — for the mesh clearance of a keyed pair (3)
Δ = Ā + r̄_1 + δ̄_11 + S̄_11 + r̄_2 + δ̄_21 + S̄_21 + δ̄_22 + S̄_22, without a key (4); for the tooth
direction α_0 = Σ ᾱ_i over three (5) or seven (6) angular deviations. The article writes these
sums of vectors and computes no tolerances; the two methods below are the standard ones its
reference [3] (Солонин, «Расчёт сборочных и технологических размерных цепей», 1980) and
ГОСТ 16320-80 give, in the issue's notation (ξ_i = +1 for an increasing link, −1 for a
decreasing one):

- nominal: A_Δ = Σ ξ_i·A_i;
- maximum–minimum (worst case): ES_Δ = Σ_{increasing} ES_i − Σ_{decreasing} EI_i,
  EI_Δ = Σ_{increasing} EI_i − Σ_{decreasing} ES_i, so T_Δ = Σ T_i;
- probabilistic: T_Δ = t·√(Σ λ_i²·T_i²), λ² = 1/9 (normal), 1/6 (triangle), 1/3 (uniform),
  t the normal law's quantile for the risk P that the closing link falls outside
  (P = 0.27 % → t = 3); the middle deviation E_cΔ = Σ ξ_i·(E_ci + α_i·T_i/2),
  ES_Δ = E_cΔ + T_Δ/2, EI_Δ = E_cΔ − T_Δ/2.

A link's share: T_i/ΣT in the worst case, λ_i²T_i²/Σλ²T² (its part of the variance) in the
probabilistic method; the largest share names the link to tighten first. All values in SI
(metres or radians); the chain's ``unit_si`` turns them back into the file's unit.
"""

from __future__ import annotations

import math
from statistics import NormalDist

from ..errors import TmmError
from ..limits import CHAIN_RISK_PCT
from ..notes import Note
from ..records import record
from .chain_input import Chain

RISK_DEFAULT_PCT = 0.27
"""The default risk P [%]: t = 3."""


@record
class Limits:
    """The closing link by one method [SI]: deviations, tolerance, limits; t and P for the
    probabilistic method (None for the worst case)."""

    es: float
    ei: float
    tolerance: float
    max: float
    min: float
    middle: float  # E_cΔ
    t: float | None = None
    risk_percent: float | None = None


@record
class Share:
    """A link's part of the closing link's tolerance (shares are fractions of 1)."""

    name: str
    sign: int
    tolerance: float
    worst_case: float  # T_i / ΣT
    probabilistic: float  # λ²T² / Σλ²T²


@record
class ChainResult:
    """The closing link of ``chain`` by both methods, and the links' shares."""

    chain: Chain
    nominal: float
    worst_case: Limits
    probabilistic: Limits
    shares: tuple[Share, ...]
    largest_worst_case: str
    largest_probabilistic: str
    notes: tuple[Note, ...] = ()

    @property
    def probabilistic_exceeds_worst_case(self) -> bool:
        """t·√(Σλ²T²) > ΣT: too few links (or uniform ones) for the probabilistic method."""
        return self.probabilistic.tolerance > self.worst_case.tolerance * (1 + 1e-12)


def t_for_risk(risk_percent: float) -> float:
    """t: the two-sided quantile of the normal law for the risk P [%] (1 − P/100 of the closing
    links fall within ±t·σ).

    >>> [round(t_for_risk(p), 3) for p in (0.27, 1.0, 4.55, 31.73)]
    [3.0, 2.576, 2.0, 1.0]
    """
    return NormalDist().inv_cdf(1.0 - risk_percent / 200.0)


def check_risk(risk_percent) -> float:
    """``risk_percent`` as a float within ``limits.CHAIN_RISK_PCT``, else TmmError."""
    lo, hi = CHAIN_RISK_PCT
    if isinstance(risk_percent, bool) or not isinstance(risk_percent, (int, float)) \
            or not math.isfinite(risk_percent) or not lo <= risk_percent <= hi:
        raise TmmError(f"--risk is {risk_percent}; give the risk in percent, {lo:g} to {hi:g} (0.27 gives t = 3)")
    return float(risk_percent)


def worst_case(chain: Chain) -> Limits:
    """The maximum–minimum method (the module's text) [SI].

    >>> from .chain_input import Link
    >>> mk = lambda n, a, es, ei, s: Link(n, a, es, ei, s, "normal", 1 / 9, 0.0)
    >>> ch = Chain("ex", "m", 1.0, False, (mk("A", 100, .1, -.1, 1), mk("B", 40, 0, -.05, -1), mk("C", 59.5, .02, -.02, -1)))
    >>> w = worst_case(ch); round(w.es, 9), round(w.ei, 9), round(w.tolerance, 9), round(w.max, 9), round(w.min, 9)
    (0.17, -0.12, 0.29, 0.67, 0.38)
    """
    nominal = sum(k.sign * k.nominal for k in chain.links)
    es = sum(k.es if k.sign > 0 else -k.ei for k in chain.links)
    ei = sum(k.ei if k.sign > 0 else -k.es for k in chain.links)
    return Limits(es=es, ei=ei, tolerance=es - ei, max=nominal + es, min=nominal + ei, middle=0.5 * (es + ei))


def probabilistic(chain: Chain, risk_percent: float = RISK_DEFAULT_PCT) -> Limits:
    """The probabilistic method (the module's text) [SI].

    The same three links, all normal, P = 0.27 %: T = 3·√((0.2² + 0.05² + 0.04²)/9) = 0.21,
    E_c = −(−0.025) = 0.025.

    >>> from .chain_input import Link
    >>> mk = lambda n, a, es, ei, s: Link(n, a, es, ei, s, "normal", 1 / 9, 0.0)
    >>> ch = Chain("ex", "m", 1.0, False, (mk("A", 100, .1, -.1, 1), mk("B", 40, 0, -.05, -1), mk("C", 59.5, .02, -.02, -1)))
    >>> p = probabilistic(ch); round(p.tolerance, 4), round(p.middle, 9), round(p.max, 4), round(p.min, 4)
    (0.21, 0.025, 0.63, 0.42)
    """
    risk = check_risk(risk_percent)
    t = t_for_risk(risk)
    nominal = sum(k.sign * k.nominal for k in chain.links)
    middle = sum(k.sign * (k.middle + k.asymmetry * k.tolerance / 2.0) for k in chain.links)
    tolerance = t * math.sqrt(sum(k.lambda2 * k.tolerance**2 for k in chain.links))
    es, ei = middle + tolerance / 2.0, middle - tolerance / 2.0
    return Limits(es=es, ei=ei, tolerance=tolerance, max=nominal + es, min=nominal + ei, middle=middle, t=t,
                  risk_percent=risk)


def solve_chain(chain: Chain, risk_percent: float = RISK_DEFAULT_PCT) -> ChainResult:
    """The closing link of ``chain`` by both methods, and each link's share (the module's text)."""
    if not chain.links:
        raise TmmError("the chain has no links; add [[link]] tables with name, nominal, es, ei, sign")
    total_t = sum(k.tolerance for k in chain.links)
    total_v = sum(k.lambda2 * k.tolerance**2 for k in chain.links)
    shares = tuple(Share(name=k.name, sign=k.sign, tolerance=k.tolerance,
                         worst_case=k.tolerance / total_t if total_t > 0 else 0.0,
                         probabilistic=k.lambda2 * k.tolerance**2 / total_v if total_v > 0 else 0.0)
                   for k in chain.links)
    wc, prob = worst_case(chain), probabilistic(chain, risk_percent)
    notes = []
    if any(k.clearance is not None for k in chain.links):
        notes.append(Note.make("chain_beta", "assumption"))
    if prob.tolerance > wc.tolerance * (1 + 1e-12):
        notes.append(Note.make("chain_probabilistic_exceeds", "warning", tp=prob.tolerance / chain.unit_si,
                               tw=wc.tolerance / chain.unit_si))
    return ChainResult(
        chain=chain, nominal=sum(k.sign * k.nominal for k in chain.links), worst_case=wc,
        probabilistic=prob, shares=shares,
        largest_worst_case=max(shares, key=lambda s: s.worst_case).name,
        largest_probabilistic=max(shares, key=lambda s: s.probabilistic).name, notes=tuple(notes))
