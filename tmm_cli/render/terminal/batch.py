"""The batch summary as a rich table (the same rows as summary.csv, the key numbers only)."""

from __future__ import annotations

from pathlib import Path

from ...i18n import ntr, tr
from ...i18n.numbers import num


def _num(value, lang: str, decimals: int) -> str:
    if value is None or value == "":
        return "—"
    try:
        return num(float(value), lang, decimals=decimals)
    except (TypeError, ValueError):
        return str(value)


def print_batch_intro(console, lang: str, *, roster=None, default_crank: bool = False) -> None:
    """Said once, before the rows: the roster's encoding and separator, or that every row uses
    the book's crank speed (a --variants run without --crank-rpm)."""
    from . import escape

    if roster is not None:
        sep = tr(lang, "';'") if roster.delimiter == ";" else tr(lang, "','")
        console.print("[cyan]ℹ[/] " + escape(tr(lang, "Roster {path}: read as {encoding}, separator {sep}.").format(path=roster.path, encoding=roster.encoding, sep=sep)))
    from ...gears.drive import DEFAULT_CRANK_RPM

    if roster is not None and roster.jobs and any(j.crank_rpm is None for j in roster.jobs):
        n = sum(j.crank_rpm is None for j in roster.jobs)
        if n == len(roster.jobs):
            default_crank = True
        else:
            console.print("[cyan]ℹ[/] " + ntr(
                lang, "{n} row without crank_rpm uses the book's crank speed n_cr = {rpm:g} rpm (§2.4).",
                "{n} rows without crank_rpm use the book's crank speed n_cr = {rpm:g} rpm (§2.4).", n).format(
                n=n, rpm=DEFAULT_CRANK_RPM))
    if default_crank:

        console.print("[cyan]ℹ[/] " + tr(lang, "Every row uses the book's crank speed n_cr = {DEFAULT_CRANK_RPM:g} rpm (§2.4); give --crank-rpm or a roster with a crank_rpm column for the students' own speeds.").format(DEFAULT_CRANK_RPM=DEFAULT_CRANK_RPM))


def print_batch(console, summary, out_dir: Path, lang: str) -> None:
    from rich import box
    from . import escape
    from rich.table import Table

    from ..data.summary import STATUS, flag_name

    roster = any(not str(r["student"]).startswith("variant ") for r in summary.rows)
    t = Table(title=tr(lang, "Batch summary"), header_style="bold", box=box.SIMPLE_HEAD, pad_edge=False)
    heads = ([tr(lang, "Student")] if roster else []) + [
        tr(lang, "Var"), "n_d" if lang != "ru" else "n_д", "i_pl" if lang != "ru" else "i_пл",
        tr(lang, "teeth × k"), "z1/z2", "ε_α",
        tr(lang, "r0, mm"), "e|l_OC", tr(lang, "ν_rise/ν_ret, °"), tr(lang, "warnings"),
    ]
    for i, head in enumerate(heads):
        t.add_column(head, justify="left" if (roster and i == 0) or i == len(heads) - 1 else "right",
                     no_wrap=not ((roster and i == 0) or i == len(heads) - 1))
    for r in summary.rows:
        lead = [escape(str(r["student"]))] if roster else []
        if r["status"] != "ok":
            colour = "red" if r["status"] == "failed" else "yellow"
            t.add_row(*lead, escape(str(r["variant"] or "—")), "[" + colour + "]" + tr(lang, STATUS[r["status"]]) + "[/]",
                      *[""] * (len(heads) - len(lead) - 2))
            continue
        other = r["e_mm"] if r.get("e_mm") not in (None, "") else r["l_oc_mm"]
        nu = _num(r["nu_rise_deg"], lang, 1) + "/" + _num(r.get("nu_return_deg"), lang, 1)
        warn = ", ".join(flag_name(f, lang) for f in r.get("warnings") or ()) or "—"
        t.add_row(
            *lead, str(r["variant"]), _num(r["n_motor_rpm"], lang, 0), _num(r["i_planetary"], lang, 3),
            f"{r['teeth']} × {r['planets']}", f"{r['z1']}/{r['z2']}", _num(r["eps_alpha"], lang, 3),
            _num(r["r0_mm"], lang, 2), _num(other, lang, 2), nu, escape(warn),
        )
    console.print(t)
    from ...i18n.errors import error_text

    for r in summary.failed:
        if r["status"] == "failed":
            console.print(f"[red]✘[/] {escape(str(r['student']))}: {escape(error_text(str(r['error']), lang))}")
    ok = len(summary.rows) - len(summary.failed)
    n_failed = sum(r["status"] == "failed" for r in summary.rows)
    if not summary.summary_path:  # no row could run: nothing was written
        console.print(tr(lang, "no row can run: nothing was run, and {out} was left as it was").format(
            out=escape(str(out_dir))))
        return
    path = escape(summary.summary_path)
    console.print(tr(lang, "{ok} done, {n_failed} failed; summary: {path}").format(ok=ok, n_failed=n_failed, path=path))
