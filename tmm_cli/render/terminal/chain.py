"""Rich tables of `tmm chain` (seed 003, second article): the links with their shares, the closing
link by both methods, and a summary. Read from the :class:`~tmm_cli.accuracy.chain.ChainResult`;
only the unit is changed back to the chain file's.
"""

from __future__ import annotations

from ...accuracy.chain import ChainResult
from ...i18n.lang import pick
from ...i18n.numbers import num

UNIT_LABELS = {"mm": ("mm", "мм"), "um": ("µm", "мкм"), "µm": ("µm", "мкм"), "rad": ("rad", "рад"),
               "mrad": ("mrad", "мрад"), "urad": ("µrad", "мкрад"), "µrad": ("µrad", "мкрад"), "deg": ("°", "°"),
               "arcmin": ("′", "′"), "arcsec": ("″", "″")}
DISTRIBUTIONS = {"normal": ("normal 1/9", "норм. 1/9"), "triangle": ("triangle 1/6", "Симпс. 1/6"),
                 "uniform": ("uniform 1/3", "равн. 1/3")}


def unit_label(units: str, lang: str) -> str:
    en, ru = UNIT_LABELS.get(units, (units, units))
    return pick(lang, en, ru)


def _table(title: str, *cols: tuple[str, str], caption: str | None = None):
    from rich.table import Table

    t = Table(title=title, header_style="bold", title_justify="left", caption=caption, caption_justify="left")
    for name, justify in cols:
        t.add_column(name, justify=justify, overflow="fold")
    return t


def _v(x: float, unit: float, lang: str) -> str:
    return num(x / unit, lang, sig=5, sci=False)


def _pct(x: float, lang: str) -> str:
    return num(100.0 * x, lang, decimals=1)


def _links_table(res: ChainResult, lang: str):
    chain = res.chain
    u = chain.unit_si
    unit = unit_label(chain.units, lang)
    t = _table(pick(lang, f"Links, {unit}", f"Составляющие звенья, {unit}"),
               ("№", "right"), (pick(lang, "Link", "Звено"), "left"), ("ξ", "center"),
               (pick(lang, "Nominal", "Номинал"), "right"), ("ES", "right"), ("EI", "right"), ("T", "right"),
               (pick(lang, "Law, λ²", "Закон, λ²"), "left"), ("α", "right"),
               (pick(lang, "Share of ΣT, %", "Доля ΣT, %"), "right"),
               (pick(lang, "Share of variance, %", "Доля дисперсии, %"), "right"),
               caption=pick(lang, "ξ: + the link increases the closing link, − decreases it. Laws: normal, triangle "
                                  "(Simpson), uniform, with λ². β = ±arctg(δ/l): a hub's turn in its radial clearance δ "
                                  "over the length l, mm (Abdullaev, Rasulov).",
                            "ξ: + увеличивающее звено, − уменьшающее. Законы: нормальный, Симпсона, равной "
                            "вероятности, с λ². β = ±arctg(δ/l) — поворот ступицы в радиальном зазоре δ на длине l, мм "
                            "(Абдуллаев, Расулов)."))
    for i, (link, share) in enumerate(zip(chain.links, res.shares), 1):
        name = link.name
        if link.clearance is not None:
            name += f" = arctg({num(link.clearance * 1e3, lang, sig=6)}/{num(link.length * 1e3, lang, sig=6)})"
        law = pick(lang, *DISTRIBUTIONS[link.distribution])
        mark = "[bold]" if share.name == res.largest_probabilistic else ""
        t.add_row(str(i), name, "+" if link.sign > 0 else "−", _v(link.nominal, u, lang), _v(link.es, u, lang),
                  _v(link.ei, u, lang), _v(link.tolerance, u, lang), law, num(link.asymmetry, lang, sig=3),
                  _pct(share.worst_case, lang), f"{mark}{_pct(share.probabilistic, lang)}" + ("[/]" if mark else ""))
    return t


def _closing_table(res: ChainResult, lang: str):
    u = res.chain.unit_si
    unit = unit_label(res.chain.units, lang)
    p = res.probabilistic
    t = _table(pick(lang, f"Closing link, {unit}", f"Замыкающее звено, {unit}"),
               (pick(lang, "Method", "Метод"), "left"), (pick(lang, "Nominal", "Номинал"), "right"),
               ("ES", "right"), ("EI", "right"), ("T", "right"), (pick(lang, "Max", "Наибольшее"), "right"),
               (pick(lang, "Min", "Наименьшее"), "right"), ("E_c", "right"))
    for label, lim in ((pick(lang, "maximum–minimum", "максимума-минимума"),
                        res.worst_case),
                       (pick(lang, f"probabilistic, P = {num(p.risk_percent, lang, sig=4)} %, t = "
                                   f"{num(p.t, lang, decimals=2)}",
                             f"вероятностный, P = {num(p.risk_percent, lang, sig=4)} %, t = {num(p.t, lang, decimals=2)}"),
                        p)):
        t.add_row(label, _v(res.nominal, u, lang), _v(lim.es, u, lang), _v(lim.ei, u, lang),
                  _v(lim.tolerance, u, lang), _v(lim.max, u, lang), _v(lim.min, u, lang), _v(lim.middle, u, lang))
    return t


def summary_lines(res: ChainResult, lang: str) -> list[str]:
    shares = {s.name: s for s in res.shares}
    big = shares[res.largest_probabilistic]
    lines = [pick(lang,
                  f"The largest contributor: {big.name} ({_pct(big.probabilistic, lang)} % of the variance, "
                  f"{_pct(big.worst_case, lang)} % of ΣT); tighten it first.",
                  f"Наибольший вклад: {big.name} ({_pct(big.probabilistic, lang)} % дисперсии, "
                  f"{_pct(big.worst_case, lang)} % от ΣT) — его допуск ужесточать в первую очередь.")]
    if res.largest_worst_case != res.largest_probabilistic:
        wc = shares[res.largest_worst_case]
        lines.append(pick(lang, f"By the worst case the largest is {wc.name} ({_pct(wc.worst_case, lang)} % of ΣT).",
                          f"По методу максимума-минимума наибольший вклад у {wc.name} ({_pct(wc.worst_case, lang)} % от ΣT)."))
    return lines


def print_chain(console, res: ChainResult, lang: str) -> None:
    name = res.chain.name or pick(lang, "Dimensional chain", "Размерная цепь")
    console.print(f"[bold]{name}[/] " + pick(lang, "(dimensional chain; Abdullaev, Rasulov)",
                                             "(размерная цепь; Абдуллаев, Расулов)"))
    console.print(_links_table(res, lang))
    console.print(_closing_table(res, lang))
    for line in summary_lines(res, lang):
        console.print(line)
