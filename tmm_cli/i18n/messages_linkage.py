"""Sentences for the linkage notes (sheet 1, seed 003), ru and en; `note_text` formats them."""

from . import N_

MESSAGES: dict[str, str] = {
    "linkage_whitworth": N_("O41 lies inside the crank circle: a true Whitworth mechanism, the slotted link turns fully; the block slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41, so the slot must be at least {rho_max_mm:.1f} mm long (B is at r2 = {r2_mm:.1f} mm)."),
    "linkage_crank_shaper": N_("O41 lies outside the crank circle: a crank-shaper, the slotted link swings through {swing_deg:.2f}°; the block slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41."),
    "linkage_eps": N_("The crank's ε21 = {eps:g} rad/s² is applied at every position with the same ω21 = {omega:.4g} rad/s (the instantaneous state of each position); the angle axis and K assume uniform rotation."),
    "linkage_rod_angle": N_("The rod BC leans up to {angle_deg:.1f}° from the ram's guide (more than {limit_deg:.0f}°): the ram is pushed at a poor angle; lengthen the rod (--r3) or move the guide (--b) towards B's path."),
    "linkage_near_pivot": N_("The block passes within {rho_min_mm:.2f} mm of the link's pivot O41: the link turns up to {ratio:.1f} times as fast as the crank."),
    "linkage_reversals": N_("The ram stops {count} times per crank turn (not only at the two dead positions); H and K are taken between its extreme positions."),
    "mechanism_name_script": N_("The mechanism's name «{name}» is not written in the letters of the document's language; it is printed on the sheets and in the note as the file gives it (change `name` in the file to change it)."),
    "mechanism_position0_working": N_("Position 0 is the extreme position of the output link where the working stroke begins; the working stroke is the slower one (the larger crank angle)."),
    "mechanism_position0_load": N_("Position 0 is the extreme position of the output link where the working stroke begins, the stroke the file's load.working names."),
    "mechanism_position0_far": N_("Both strokes take the same crank angle (K = 1): position 0 is the extreme position of the output link farthest from the crank pivot (the top dead centre); give load.working or crank.start_deg to choose another."),
    "mechanism_position0_gas": N_("Position 0 is the dead centre of the first gas load's piston nearest its cylinder head (the start of its indicator diagram)."),
    "mechanism_position0_given": N_("Position 0 is at the crank angle the file gives (crank.start_deg)."),
    "mechanism_position0_turning": N_("The output link turns fully and has no extreme positions: there is no stroke and no K; position 0 is at the crank angle 0° (or crank.start_deg)."),
    "mechanism_fast_working": N_("The working stroke is the faster one (K = {time_ratio:.4f} < 1): the output moves faster "
                                 "under the load than on the return, where a machine usually has K ≥ 1; check "
                                 "load.working or the crank's sense."),
    "mechanism_stops": N_("The output link stops {count} times per crank turn (not only in its two extreme positions); the stroke and K are taken between its extreme positions."),
    "mechanism_pressure": N_("The pressure angle of group {group} reaches {angle_deg:.1f}° at φ = {phi_deg:.1f}° (more than {limit_deg:.0f}°): the group transmits motion poorly there."),
    "mechanism_slot": N_("The block slides along the slotted link {link} from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from its pivot {pivot}: the slot must reach at least {rho_max_mm:.1f} mm."),
    # sheet 2 of a mechanism file (issue 25): forces and the flywheel; tmm project --mechanism
    "dynamics_uniform": N_("The force analysis takes the crank turning uniformly at its mean speed n₁ = {rpm:.5g} rpm (ε₁ = 0), as the kinetostatic method does; the pairs are frictionless."),
    "dynamics_gravity": N_("The links' weights G = m·g (g = 9.81 m/s², towards −y) are counted."),
    "dynamics_no_gravity": N_("The links' weights are not counted (the file has no gravity = true)."),
    "dynamics_massless": N_("The file gives no [[mass]]: the links are massless (no inertia forces, no weights)."),
    "dynamics_no_load": N_("The file gives no [load]: only the inertia forces and the weights act."),
    "dynamics_no_table": N_("The file has no [dynamics] table: the flywheel is not computed; give delta = … (and J_rotor) for it."),
    "dynamics_no_flywheel": N_("No flywheel is needed: the mechanism and the rotor alone keep the speed within δ = {delta:.4g} (δ = {delta_actual:.4g} without a flywheel)."),
    "dynamics_methods": N_("The flywheel is Mertsalov's; Wittenbauer's energy–mass diagram gives J_fl = {j_w:.4g} kg·m² (Mertsalov's differs by {diff_pct:+.2f} %: it neglects the change of the second group's energy with the speed)."),
    "dynamics_motor": N_("Over a cycle the gas forces do more work than they take: the mechanism is a motor; the constant moment it gives the machine is {moment:.4g} N·m (the driving moment M_d is negative: the machine's resistance)."),
    "dynamics_driving_negative": N_("The driving moment comes out negative (M_d = {moment:.4g} N·m): over a turn the loads give work to the crank; check the load's direction and load.working."),
    "project_engine_consumer": N_("The mechanism of sheet 2 is an engine: sheet 4 takes its consumer's resisting moment M_c = {torque:.4g} N·m as the moment the gear train passes from the crank to the consumer, and the choice of an electric motor there is only a formal check of the train's load (an engine needs none)."),
    "project_mechanism_motor": N_("Sheet 4 takes the mean reduced moment M = {torque:.4g} N·m (the driving moment of sheet 2) and the crank speed n_cr = {rpm:.5g} rpm from the mechanism file {file}."),
    # tmm synth (issue 33): the synthesis of a lever mechanism from its task
    "synth_best_pivot": N_("The crank's pivot A is the point of the locus of θ where the smallest transmission angle is largest: γ_min = {gamma_deg:.2f}° (the book leaves the point to the designer; give frame = … to choose another)."),
    "synth_frame_pivot": N_("The crank's pivot A is where the circle of radius l_AD = {frame_mm:.1f} mm about D meets the locus of θ (of the points there, the one with the larger γ_min = {gamma_deg:.2f}°; the best on the locus is {best_deg:.2f}°)."),
    "synth_low_transmission": N_("The smallest transmission angle is {gamma_deg:.1f}° (less than {limit_deg:.0f}°), the largest any crank's pivot on the locus of θ gives: the rocker is driven at a poor angle; lower time_ratio or swing_deg."),
    "synth_low_transmission_frame": N_("The smallest transmission angle is {gamma_deg:.1f}° (less than {limit_deg:.0f}°): the rocker is driven at a poor angle; give {frame_toml} (γ_min = {best_deg:.1f}° there), or remove frame and give min_transmission_deg = {limit_deg:.0f}."),
    "synth_slider_pressure": N_("The largest pressure angle on the slider is {alpha_deg:.1f}° with λ = l_OA/l_AB = {lam:.3f}: near or above the usual {limit_deg:.0f}° (λ usually 0.2 … 0.35) — a legal but poor design, the slider wedges in its guide; lower time_ratio or offset, or give a smaller lambda."),
    "synth_default_rpm": N_("The task gives no crank speed: the mechanism file has rpm = {rpm:g}; put the machine's speed there (the lengths do not depend on it)."),
    "synth_rod_ratio": N_("The task gives no rod_ratio: l_BC = {ratio:g}·l_O2B (the usual 0.25 … 0.35 of shaper schemes)."),
    "synth_slot": N_("The block slides up to {slot_mm:.1f} mm from O2, beyond B ({link_mm:.1f} mm): the slotted link must be at least {slot_mm:.1f} mm long."),
    "synth_mirror": N_("The mechanism is written mirrored, so that the working stroke the task names (load.working) is the slower one."),
    "synth_fast_working": N_("The task's load.working makes the working stroke the faster one (K = {time_ratio:.4f} as tmm linkage counts it)."),
}
