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
}
