"""Rich tables of `tmm chain` (seed 003, second article): the links with their shares, the closing
link by both methods, and a summary. Read from the :class:`~tmm_cli.accuracy.chain.ChainResult`;
only the unit is changed back to the chain file's.
"""

from __future__ import annotations

from . import escape
from ...accuracy.chain import ChainResult
from ...i18n import N_, tr
from ...i18n.numbers import num

UNIT_LABELS = {"mm": N_("mm"), "um": N_("µm"), "µm": N_("µm"), "rad": N_("rad"), "mrad": N_("mrad"),
               "urad": N_("µrad"), "µrad": N_("µrad"), "deg": "°", "arcmin": "′", "arcsec": "″"}
DISTRIBUTIONS = {"normal": N_("normal 1/9"), "triangle": N_("triangle 1/6"), "uniform": N_("uniform 1/3")}


def unit_label(units: str, lang: str) -> str:
    return tr(lang, UNIT_LABELS.get(units, units))


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
    t = _table(tr(lang, "Links, {unit}").format(unit=unit),
               ("№", "right"), (tr(lang, "Link"), "left"), ("ξ", "center"),
               (tr(lang, "Nominal"), "right"), ("ES", "right"), ("EI", "right"), ("T", "right"),
               (tr(lang, "Law, λ²"), "left"), ("α", "right"),
               (tr(lang, "Share of ΣT, %"), "right"),
               (tr(lang, "Share of variance, %"), "right"),
               caption=tr(lang, "ξ: + the link increases the closing link, − decreases it. Laws: normal, triangle (Simpson), uniform, with λ². β = ±arctg(δ/l): a hub's turn in its radial clearance δ over the length l, mm (Abdullaev, Rasulov)."))
    for i, (link, share) in enumerate(zip(chain.links, res.shares), 1):
        name = escape(link.name)  # a person's text: "[/x]" is text
        if link.clearance is not None:
            name += f" = arctg({num(link.clearance * 1e3, lang, sig=6)}/{num(link.length * 1e3, lang, sig=6)})"
        law = tr(lang, DISTRIBUTIONS[link.distribution])
        mark = "[bold]" if share.name == res.largest_probabilistic else ""
        t.add_row(str(i), name, "+" if link.sign > 0 else "−", _v(link.nominal, u, lang), _v(link.es, u, lang),
                  _v(link.ei, u, lang), _v(link.tolerance, u, lang), law, num(link.asymmetry, lang, sig=3),
                  _pct(share.worst_case, lang), f"{mark}{_pct(share.probabilistic, lang)}" + ("[/]" if mark else ""))
    return t


def _closing_table(res: ChainResult, lang: str):
    u = res.chain.unit_si
    unit = unit_label(res.chain.units, lang)
    p = res.probabilistic
    t = _table(tr(lang, "Closing link, {unit}").format(unit=unit),
               (tr(lang, "Method"), "left"), (tr(lang, "Nominal"), "right"),
               ("ES", "right"), ("EI", "right"), ("T", "right"), (tr(lang, "Max"), "right"),
               (tr(lang, "Min"), "right"), ("E_c", "right"))
    for label, lim in ((tr(lang, "maximum–minimum"),
                        res.worst_case),
                       (tr(lang, "probabilistic, P = {risk_percent} %, t = {t}").format(risk_percent=num(p.risk_percent, lang, sig=4), t=num(p.t, lang, decimals=2)),
                        p)):
        t.add_row(label, _v(res.nominal, u, lang), _v(lim.es, u, lang), _v(lim.ei, u, lang),
                  _v(lim.tolerance, u, lang), _v(lim.max, u, lang), _v(lim.min, u, lang), _v(lim.middle, u, lang))
    return t


def summary_lines(res: ChainResult, lang: str) -> list[str]:
    shares = {s.name: s for s in res.shares}
    big = shares[res.largest_probabilistic]
    lines = [tr(lang, "The largest contributor: {name} ({probabilistic} % of the variance, {worst_case} % of ΣT); tighten it first.").format(name=big.name, probabilistic=_pct(big.probabilistic, lang), worst_case=_pct(big.worst_case, lang))]
    if res.largest_worst_case != res.largest_probabilistic:
        wc = shares[res.largest_worst_case]
        lines.append(tr(lang, "By the worst case the largest is {name} ({worst_case} % of ΣT).").format(name=wc.name, worst_case=_pct(wc.worst_case, lang)))
    return lines


def print_chain(console, res: ChainResult, lang: str) -> None:
    name = escape(res.chain.name) if res.chain.name else tr(lang, "Dimensional chain")
    console.print(f"[bold]{name}[/] " + tr(lang, "(dimensional chain; Abdullaev, Rasulov)"))
    console.print(_links_table(res, lang))
    console.print(_closing_table(res, lang))
    for line in summary_lines(res, lang):
        console.print(escape(line))
