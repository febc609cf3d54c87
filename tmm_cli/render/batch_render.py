"""The batch summary as a rich table (the same rows as summary.csv, the key numbers only)."""

from __future__ import annotations

from pathlib import Path

from .i18n import pick


def _num(value, fmt: str) -> str:
    if value is None or value == "":
        return "—"
    try:
        return fmt.format(float(value))
    except (TypeError, ValueError):
        return str(value)


def print_batch(console, summary, out_dir: Path, lang: str) -> None:
    from rich import box
    from rich.table import Table

    roster = any(not str(r["student"]).startswith("variant ") for r in summary.rows)
    t = Table(title=pick(lang, "Batch summary", "Сводка по группе"), header_style="bold", box=box.SIMPLE_HEAD, pad_edge=False)
    heads = ([pick(lang, "Student", "Студент")] if roster else []) + [
        pick(lang, "Var", "Вар"), "n_d", "i_pl", pick(lang, "teeth × k", "зубья × k"), "z1/z2", "ε_α",
        "r0, mm", "e|l_OC", "ν_у/ν_в, °", pick(lang, "warn.", "предупр."),
    ]
    for i, head in enumerate(heads):
        t.add_column(head, justify="left" if (roster and i == 0) else "right", no_wrap=not (roster and i == 0))
    for r in summary.rows:
        lead = [str(r["student"])] if roster else []
        if r["status"] != "ok":
            t.add_row(*lead, str(r["variant"] or "—"), f"[red]{pick(lang, 'failed', 'ошибка')}[/]",
                      *[""] * (len(heads) - len(lead) - 2))
            continue
        other = r["e_mm"] if r.get("e_mm") not in (None, "") else r["l_oc_mm"]
        nu = _num(r["nu_rise_deg"], "{:.1f}") + "/" + _num(r.get("nu_return_deg"), "{:.1f}")
        t.add_row(
            *lead, str(r["variant"]), _num(r["n_motor_rpm"], "{:.0f}"), _num(r["i_planetary"], "{:.3f}"),
            f"{r['teeth']} × {r['planets']}", f"{r['z1']}/{r['z2']}", _num(r["eps_alpha"], "{:.3f}"),
            _num(r["r0_mm"], "{:.2f}"), _num(other, "{:.2f}"), nu, str(r["warnings"]),
        )
    console.print(t)
    for r in summary.failed:
        console.print(f"[red]✘[/] {r['student']}: {r['error']}")
    ok = len(summary.rows) - len(summary.failed)
    console.print(pick(lang, f"{ok} done, {len(summary.failed)} failed; summary: {Path(out_dir) / 'summary.csv'}",
                       f"выполнено {ok}, с ошибкой {len(summary.failed)}; сводка: {Path(out_dir) / 'summary.csv'}"))
