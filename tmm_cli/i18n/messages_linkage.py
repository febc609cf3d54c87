"""Sentences for the linkage notes (sheet 1, seed 003), ru and en; `note_text` formats them."""

MESSAGES: dict[str, dict[str, str]] = {
    "linkage_whitworth": {
        "en": "O41 lies inside the crank circle: a true Whitworth mechanism, the slotted link turns fully; the block "
              "slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41, so the slot must be at least "
              "{rho_max_mm:.1f} mm long (B is at r2 = {r2_mm:.1f} mm).",
        "ru": "Точка O41 внутри окружности кривошипа: механизм Витворта, кулиса вращается полностью; камень "
              "скользит от {rho_min_mm:.1f} до {rho_max_mm:.1f} мм от O41, поэтому паз кулисы должен быть не короче "
              "{rho_max_mm:.1f} мм (точка B на r2 = {r2_mm:.1f} мм).",
    },
    "linkage_crank_shaper": {
        "en": "O41 lies outside the crank circle: a crank-shaper, the slotted link swings through {swing_deg:.2f}°; the "
              "block slides from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from O41.",
        "ru": "Точка O41 вне окружности кривошипа: кулисный механизм с качающейся кулисой, размах кулисы "
              "{swing_deg:.2f}°; камень скользит от {rho_min_mm:.1f} до {rho_max_mm:.1f} мм от O41.",
    },
    "linkage_eps": {
        "en": "The crank's ε21 = {eps:g} rad/s² is applied at every position with the same ω21 = {omega:.4g} rad/s "
              "(the instantaneous state of each position); the angle axis and K assume uniform rotation.",
        "ru": "Угловое ускорение кривошипа ε21 = {eps:g} рад/с² учтено в каждом положении при одной и той же "
              "ω21 = {omega:.4g} рад/с (мгновенное состояние); ось углов и K — для равномерного вращения.",
    },
    "linkage_rod_angle": {
        "en": "The rod BC leans up to {angle_deg:.1f}° from the ram's guide (more than {limit_deg:.0f}°): the ram is "
              "pushed at a poor angle; lengthen the rod (--r3) or move the guide (--b) towards B's path.",
        "ru": "Шатун BC отклоняется от направляющей ползуна до {angle_deg:.1f}° (больше {limit_deg:.0f}°): "
              "ползун толкается под невыгодным углом; удлините шатун (--r3) или сдвиньте направляющую (--b).",
    },
    "linkage_near_pivot": {
        "en": "The block passes within {rho_min_mm:.2f} mm of the link's pivot O41: the link turns up to "
              "{ratio:.1f} times as fast as the crank.",
        "ru": "Камень проходит на расстоянии {rho_min_mm:.2f} мм от оси кулисы O41: кулиса вращается быстрее "
              "кривошипа до {ratio:.1f} раза.",
    },
    "linkage_reversals": {
        "en": "The ram stops {count} times per crank turn (not only at the two dead positions); H and K are taken "
              "between its extreme positions.",
        "ru": "Ползун останавливается за оборот кривошипа не только в двух крайних положениях (остановок: {count}); H и K "
              "определены между крайними положениями.",
    },
    # tmm linkage MECH.toml (issue 24): any mechanism of a crank and class II groups
    "mechanism_position0_working": {
        "en": "Position 0 is the extreme position of the output link where the working stroke begins; the working "
              "stroke is the slower one (the larger crank angle).",
        "ru": "Положение 0 — крайнее положение выходного звена в начале рабочего хода; рабочим принят более "
              "медленный ход (больший угол поворота кривошипа).",
    },
    "mechanism_position0_load": {
        "en": "Position 0 is the extreme position of the output link where the working stroke begins, the stroke "
              "the file's load.working names.",
        "ru": "Положение 0 — крайнее положение выходного звена в начале рабочего хода, указанного в load.working.",
    },
    "mechanism_position0_far": {
        "en": "Both strokes take the same crank angle (K = 1): position 0 is the extreme position of the output "
              "link farthest from the crank pivot (the top dead centre); give load.working or crank.start_deg to "
              "choose another.",
        "ru": "Оба хода занимают одинаковый угол поворота кривошипа (K = 1): положение 0 — крайнее положение "
              "выходного звена, наиболее удалённое от оси кривошипа (верхняя мёртвая точка); другое задаётся "
              "load.working или crank.start_deg.",
    },
    "mechanism_position0_given": {
        "en": "Position 0 is at the crank angle the file gives (crank.start_deg).",
        "ru": "Положение 0 — при угле кривошипа, заданном в файле (crank.start_deg).",
    },
    "mechanism_position0_turning": {
        "en": "The output link turns fully and has no extreme positions: there is no stroke and no K; position 0 "
              "is at the crank angle 0° (or crank.start_deg).",
        "ru": "Выходное звено вращается полностью и не имеет крайних положений: хода и K нет; положение 0 — при "
              "угле кривошипа 0° (или crank.start_deg).",
    },
    "mechanism_fast_working": {
        "en": "The working stroke is the faster one (K = {time_ratio:.4f} < 1): check load.working.",
        "ru": "Рабочий ход быстрее холостого (K = {time_ratio:.4f} < 1): проверьте load.working.",
    },
    "mechanism_stops": {
        "en": "The output link stops {count} times per crank turn (not only in its two extreme positions); the "
              "stroke and K are taken between its extreme positions.",
        "ru": "Выходное звено останавливается за оборот кривошипа не только в двух крайних положениях (остановок: "
              "{count}); ход и K определены между крайними положениями.",
    },
    "mechanism_pressure": {
        "en": "The pressure angle of group {group} reaches {angle_deg:.1f}° at φ = {phi_deg:.1f}° (more than "
              "{limit_deg:.0f}°): the group transmits motion poorly there.",
        "ru": "Угол давления в группе {group} достигает {angle_deg:.1f}° при φ = {phi_deg:.1f}° (больше "
              "{limit_deg:.0f}°): передача движения там неблагоприятна.",
    },
    "mechanism_slot": {
        "en": "The block slides along the slotted link {link} from {rho_min_mm:.1f} to {rho_max_mm:.1f} mm from its "
              "pivot {pivot}: the slot must reach at least {rho_max_mm:.1f} mm.",
        "ru": "Камень скользит по кулисе {link} от {rho_min_mm:.1f} до {rho_max_mm:.1f} мм от её оси {pivot}: паз "
              "должен доходить не менее чем до {rho_max_mm:.1f} мм.",
    },
}
