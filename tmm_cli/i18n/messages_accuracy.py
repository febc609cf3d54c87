"""Sentences for the notes of `tmm carrier` (seed 004) and `tmm chain` (seed 003, second article),
ru and en; `note_text` formats them."""

from . import N_

MESSAGES: dict[str, str] = {
    "carrier_parallel_cheeks": N_("The cheeks are taken as parallel (as the seed does): the centres are points (y, z) of each cheek and the axial coordinate drops out."),
    "carrier_pair_skew": N_("The skews of neighbouring axes (column e) follow the project's reconstruction, e_i = ((P′_i − P_i) − (P′_i−1 − P_i−1))·n_i: the seed's preview stops before defining them (docs/accuracy.md)."),
    "carrier_suspect": N_("Suspect: {names} (standardised residual {t:.1f}, threshold {crit:.1f}): a misread gauge? Re-measure it, or run again with --exclude {first}; the fit above still uses it."),
    "carrier_untested": N_("Only {redundant} redundant measurements: too few to test them for a misread."),
    "chain_beta": N_("A hub's turn in its clearance, β = arctg(δ/l), is taken as a deviation either way about 0 (0 ± β): the key's misalignment can turn the hub either way; the article gives only the formula."),
    "chain_probabilistic_exceeds": N_("The probabilistic tolerance {tp:.4g} exceeds the worst case {tw:.4g}: too few links (or uniform ones) for the probabilistic method; take the worst case."),
}
