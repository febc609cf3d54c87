"""Rich tables of `tmm carrier` (seed 004): the bores' errors, the plants' chord-only estimate
beside the fit, the residuals with the suspect ones marked, and a summary. Everything shown is
read from the :class:`~tmm_cli.accuracy.carrier.CarrierFit`; nothing is computed here.
"""

from __future__ import annotations

from ...accuracy.carrier import CarrierFit
from ...accuracy.measurements import KINDS
from ...i18n import tr
from ...i18n.numbers import num

UM = 1e6
MM = 1e3

KIND_LABELS = {"R": "R", "R_prime": "R′", "h": "h", "h_prime": "h′", "s": "s", "e": "e"}


def _table(title: str, *cols: tuple[str, str], caption: str | None = None):
    from rich.table import Table

    t = Table(title=title, header_style="bold", title_justify="left", caption=caption, caption_justify="left")
    for name, justify in cols:
        t.add_column(name, justify=justify, overflow="fold")
    return t


def _um(x, lang: str, decimals: int = 1) -> str:
    return num(None if x is None else x * UM, lang, decimals=decimals)


def _pm(x, u, lang: str) -> str:
    """"−16,1 ± 0,6" (µm); the uncertainty left out when there is none."""
    if u is None:
        return _um(x, lang)
    return f"{_um(x, lang)} ± {_um(u, lang)}"


def _bores_table(fit: CarrierFit, lang: str):
    um = tr(lang, "µm")
    cols = [(tr(lang, "Bore"), "right"),
            (f"Δr, {um}", "right"), (f"Δτ, {um}", "right"), (f"Δr′, {um}", "right"), (f"Δτ′, {um}", "right"),
            (f"s, {um}", "right")]
    verdict = fit.tol_radial is not None or fit.tol_tangential is not None
    if verdict:
        cols.append((tr(lang, "Verdict"), "left"))
    title = tr(lang, "Bore position errors by least squares over {used} measurements (± standard uncertainty)").format(used=fit.used)
    caption = tr(lang, "Δr = |P| − R radial, Δτ = R·(angle − θ) tangential (counter-clockwise +); unprimed: left cheek, primed: right cheek; s: skew of the bore's axis about the carrier's axis. Bore 1 of the left cheek defines the frame (Δτ1 = 0).")
    t = _table(title, *cols, caption=caption)
    for b in fit.bores:
        row = [str(b.bore), _pm(b.radial, b.u_radial, lang),
               _pm(b.tangential, b.u_tangential, lang) if b.bore > 1 else _um(0.0, lang),
               _pm(b.radial_prime, b.u_radial_prime, lang), _pm(b.tangential_prime, b.u_tangential_prime, lang),
               _um(b.skew, lang)]
        if verdict:
            row.append(tr(lang, "within") if b.within else
                       "[red]" + tr(lang, "out of tolerance") + "[/]")
        t.add_row(*row)
    return t


def _chord_only_table(fit: CarrierFit, lang: str):
    um = tr(lang, "µm")
    title = tr(lang, "The plants' chord-only estimate (seed 004, eq. (1)) beside the fit: tangential error relative "
                     "to bore 1, {um}").format(um=um)
    caption = tr(lang, "τ̂ = Σ(h_k − 2R·sin(π/z_c))/cos(π/z_c); its error from the radial errors alone, to first order: tan(π/z_c)·Σ(Δr_k + Δr_k+1) (left cheek, from the fitted Δr).")
    t = _table(title, (tr(lang, "Bore"), "right"),
               (tr(lang, "chord-only τ̂"), "right"), (tr(lang, "fit Δτ"), "right"),
               ("τ̂ − Δτ", "right"), (tr(lang, "from Δr"), "right"),
               (tr(lang, "chord-only τ̂′"), "right"), (tr(lang, "fit Δτ′ − Δτ′1"), "right"),
               ("τ̂′ − (Δτ′ − Δτ′1)", "right"), caption=caption)
    for b in fit.bores:
        t.add_row(str(b.bore), _um(b.chord_only, lang), _um(b.tangential, lang), _um(b.chord_only - b.tangential, lang),
                  _um(b.radial_bias, lang), _um(b.chord_only_prime, lang), _um(b.fit_relative_prime, lang),
                  _um(b.chord_only_prime - b.fit_relative_prime, lang))
    return t


def _residuals_table(fit: CarrierFit, lang: str):
    um = tr(lang, "µm")
    by_name = fit.residual_by_name
    kinds = [k for k in KINDS if any(f"{k}{i}" in by_name for i in range(1, fit.z_c + 1))]
    title = tr(lang, "Residuals, measured − fitted, {um}").format(um=um)
    caption = tr(lang, "In brackets: left out (--exclude); red: suspect; —: not measured.")
    t = _table(title, (tr(lang, "Bore"), "right"), *((KIND_LABELS[k], "right") for k in kinds),
               caption=caption)
    for i in range(1, fit.z_c + 1):
        row = [str(i)]
        for k in kinds:
            r = by_name.get(f"{k}{i}")
            if r is None:
                row.append("—")
                continue
            text = _um(r.residual, lang, decimals=2)
            if not r.used:
                text = f"({text})"
            if r.name in fit.suspect:
                text = f"[bold red]{text}[/]"
            row.append(text)
        t.add_row(*row)
    return t


def summary_lines(fit: CarrierFit, lang: str) -> list[str]:
    """The sentences under the tables: the fit's quality, the tolerances (suspects and assumptions
    are the fit's notes, printed after these)."""
    um = tr(lang, "µm")
    lines = []
    sigma = "—" if fit.sigma is None else _um(fit.sigma, lang, 2)
    lines.append(tr(lang, "RMS of the residuals {rms} {um}; scatter of one measurement σ = {sigma} {um} ({used} measurements, {unknowns} unknowns, {redundancy} redundant).").format(rms=_um(fit.rms, lang, 2), um=um, sigma=sigma, used=fit.used, unknowns=fit.unknowns, redundancy=fit.redundancy))
    if fit.critical_t is not None and not fit.suspect:
        crit = num(fit.critical_t, lang, decimals=1)
        lines.append(tr(lang, "No measurement stands out (every standardised residual is below {crit}).").format(crit=crit))
    if fit.excluded:
        lines.append(tr(lang, "Left out: ") + ", ".join(fit.excluded) + ".")
    if fit.tol_radial is not None or fit.tol_tangential is not None:
        parts = []
        if fit.tol_radial is not None:
            parts.append(tr(lang, "radial ±") + f"{_um(fit.tol_radial, lang)} {um}")
        if fit.tol_tangential is not None:
            parts.append(tr(lang, "tangential ±") + f"{_um(fit.tol_tangential, lang)} {um}")
        out = [str(b.bore) for b in fit.bores if not b.within]
        verdict = (tr(lang, "bores out of tolerance: ") + ", ".join(out)) if out \
            else tr(lang, "every bore is within.")
        lines.append(tr(lang, "Tolerances: ") + ", ".join(parts) + "; " + verdict)
    return lines


def print_carrier(console, fit: CarrierFit, lang: str) -> None:
    title = tr(lang, "Planet carrier: {z_c} bores on R = {v} mm (Leontiev, Nasonov, Bedny, 2012)").format(z_c=fit.z_c, v=num(fit.radius * MM, lang, sig=6))
    console.print(f"[bold]{title}[/]")
    for table in (_bores_table(fit, lang), _chord_only_table(fit, lang), _residuals_table(fit, lang)):
        console.print(table)
    for line in summary_lines(fit, lang):
        console.print(line)
