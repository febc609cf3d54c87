"""Sentences for the notes of shifted gears and the AA̅ planetary synthesis (seed 000), ru and en."""

from . import N_

MESSAGES: dict[str, str] = {
    "shift_undercut": N_("Pair {pair}: gear z = {z} is undercut — x = {x} < x_min = h_a*(17 − z)/17 = {xmin}; shift it by at least x_min."),
    "shift_tip_thin": N_("Pair {pair}: the tip of gear z = {z} is too thin — s_a = {sa} mm = {sam}·m < {limit} mm (limit 0.25·m); reduce its shift."),
    "shift_eps_low": N_("Pair {pair}: contact ratio ε_α = {eps} < 1.2 (recommended; hard limit 1.05)."),
    "shift_eps_hard": N_("Pair {pair}: contact ratio ε_α = {eps} < 1.05 — below the hard limit; the pair will not run smoothly. Reduce the shifts or the working angle."),
    "shift_interference": N_("Pair {pair}: fillet interference on gear z = {z} — the mate's tip reaches it at roll length {rho} mm, below the involute's lower limit point at {limit} mm (rack-cut gear); change the shifts."),
    "aa_planet_tip": N_("The planet is one gear meshing both wheels: its tip diameter is the smaller of the two the meshes allow, d_a = min({da12}, {da34}) = {da} mm, so the radial clearance holds in both."),
    "aa_neighbours": N_("Neighbouring fails: the planets' tip circles d_a = {da} mm do not fit {k} planets, 2a_w·sin(π/k) = {limit} mm; use fewer planets."),
    "spur_shifted_given": N_("Spur pair with the given profile shifts x1 = {x1}, x2 = {x2} (beyond the book): a_w = {aw} mm, α_w = {alpha_w}°."),
    "spur_shifted_auto": N_("Spur pair shifted by the rule --shift auto (no undercut, then x1 = −x2 when z1 + z2 ≥ 34, else each gear at its limit h_a*(17 − z)/17): x1 = {x1}, x2 = {x2}, a_w = {aw} mm, α_w = {alpha_w}°."),
    "spur_shifted_aw": N_("Spur pair at the required centre distance a_w = {aw} mm: α_w = {alpha_w}°, x_Σ split as --shift auto plus half the difference to each gear: x1 = {x1}, x2 = {x2}."),
    "spur_shift_suggest": N_("Gear z = {z} < 17 is undercut as a zero gear: shift it by x ≥ h_a*(17 − z)/17 = {x}; --shift auto gives x1 = {x1}, x2 = {x2}."),
    "aa_bar_hint": N_("Beyond the book: the planetary mechanism AA̅ with shifted gears (S. N. Kavetsky, Vestnik NTU KhPI, 2010), driven at its carrier H with the output on wheel 1, gives i_H1 = 1/i = {ratio} ({err} %) with Z = {teeth}, k = 3: tmm planetary --ratio {i} --c {c} --x1 {x1} --x2 {x2} (α_w34 = {aw34}°; every blocking-contour line holds)."),
}
