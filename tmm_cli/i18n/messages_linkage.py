"""Sentences for the linkage notes (sheet 1, seed 003), ru and en; `note_text` formats them."""

from . import N_

MESSAGES: dict[str, str] = {
    "linkage_whitworth": N_("O41 lies inside the crank circle: a true Whitworth mechanism, the slotted link turns fully; the block slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41, so the slot must be at least {rho_max_mm:.1f} mm long (B is at r2 = {r2_mm:.1f} mm)."),
    "linkage_crank_shaper": N_("O41 lies outside the crank circle: a crank-shaper, the slotted link swings through {swing_deg:.2f}°; the block slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41."),
    "linkage_eps": N_("The crank's ε21 = {eps:g} rad/s² is applied at every position with the same ω21 = {omega:.4g} rad/s (the instantaneous state of each position); the angle axis and K assume uniform rotation."),
    "linkage_rod_angle": N_("The rod BC leans up to {angle_deg:.1f}° from the ram's guide (more than {limit_deg:.0f}°): the ram is pushed at a poor angle; lengthen the rod (--r3) or move the guide (--b) towards B's path."),
    "linkage_near_pivot": N_("The block passes within {rho_min_mm:.2f} mm of the link's pivot O41: the link turns up to {ratio:.1f} times as fast as the crank."),
    "linkage_reversals": N_("The ram stops {count} times per crank turn (not only at the two dead positions); H and K are taken between its extreme positions."),
    "mechanism_position0_working": N_("Position 0 is the extreme position of the output link where the working stroke begins; the working stroke is the slower one (the larger crank angle)."),
    "mechanism_position0_load": N_("Position 0 is the extreme position of the output link where the working stroke begins, the stroke the file's load.working names."),
    "mechanism_position0_far": N_("Both strokes take the same crank angle (K = 1): position 0 is the extreme position of the output link farthest from the crank pivot (the top dead centre); give load.working or crank.start_deg to choose another."),
    "mechanism_position0_given": N_("Position 0 is at the crank angle the file gives (crank.start_deg)."),
    "mechanism_position0_turning": N_("The output link turns fully and has no extreme positions: there is no stroke and no K; position 0 is at the crank angle 0° (or crank.start_deg)."),
    "mechanism_fast_working": N_("The working stroke is the faster one (K = {time_ratio:.4f} < 1): check load.working."),
    "mechanism_stops": N_("The output link stops {count} times per crank turn (not only in its two extreme positions); the stroke and K are taken between its extreme positions."),
    "mechanism_pressure": N_("The pressure angle of group {group} reaches {angle_deg:.1f}° at φ = {phi_deg:.1f}° (more than {limit_deg:.0f}°): the group transmits motion poorly there."),
    "mechanism_slot": N_("The block slides along the slotted link {link} from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from its pivot {pivot}: the slot must reach at least {rho_max_mm:.1f} mm."),
}
