"""Sentences for the notes of `tmm carrier` (seed 004) and `tmm chain` (seed 003, second article),
ru and en; `note_text` formats them."""

MESSAGES: dict[str, dict[str, str]] = {
    "carrier_parallel_cheeks": {
        "en": "The cheeks are taken as parallel (as the seed does): the centres are points (y, z) of each cheek and "
              "the axial coordinate drops out.",
        "ru": "Щёки водила считаются параллельными (как в статье): центры расточек — точки (y, z) каждой щеки, "
              "осевая координата в расчёт не входит.",
    },
    "carrier_pair_skew": {
        "en": "The skews of neighbouring axes (column e) follow the project's reconstruction, "
              "e_i = ((P′_i − P_i) − (P′_i−1 − P_i−1))·n_i: the seed's preview stops before defining them "
              "(docs/accuracy.md).",
        "ru": "Скрещивания осей соседних расточек (столбец e) приняты по реконструкции проекта, "
              "e_i = ((P′_i − P_i) − (P′_i−1 − P_i−1))·n_i: фрагмент статьи обрывается до их определения "
              "(docs/accuracy.md).",
    },
    "carrier_suspect": {
        "en": "Suspect: {names} (standardised residual {t:.1f}, threshold {crit:.1f}): a misread gauge? Re-measure "
              "it, or run again with --exclude {first}; the fit above still uses it.",
        "ru": "Подозрительные измерения: {names} (стандартизованная невязка {t:.1f}, порог {crit:.1f}): промах при "
              "измерении? Перемерьте или запустите снова с --exclude {first}; расчёт выше его ещё учитывает.",
    },
    "carrier_untested": {
        "en": "Only {redundant} redundant measurements: too few to test them for a misread.",
        "ru": "Избыточных измерений только {redundant}: слишком мало, чтобы проверить их на промахи.",
    },
    "chain_beta": {
        "en": "A hub's turn in its clearance, β = arctg(δ/l), is taken as a deviation either way about 0 (0 ± β): the "
              "key's misalignment can turn the hub either way; the article gives only the formula.",
        "ru": "Поворот ступицы в зазоре β = arctg(δ/l) принят как отклонение в обе стороны от нуля (0 ± β): перекос "
              "шпонки может повернуть ступицу в любую сторону; в статье дана только формула.",
    },
    "chain_probabilistic_exceeds": {
        "en": "The probabilistic tolerance {tp:.4g} exceeds the worst case {tw:.4g}: too few links (or uniform ones) "
              "for the probabilistic method; take the worst case.",
        "ru": "Допуск по вероятностному методу {tp:.4g} больше, чем по методу максимума-минимума {tw:.4g}: слишком "
              "мало звеньев (или звенья с законом равной вероятности); примите метод максимума-минимума.",
    },
}
