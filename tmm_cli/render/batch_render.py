"""The batch summary as a rich table (the same rows as summary.csv)."""

from __future__ import annotations

from pathlib import Path

from .i18n import pick


def _cell(value, fmt: str = "{}") -> str:
    if value is None or value == "":
        return "—"
    if isinstance(value, float):
        return fmt.format(value)
    return str(value)


def print_batch(console, summary, out_dir: Path, lang: str) -> None:
    from rich.table import Table

    t = Table(title=pick(lang, "Batch summary", "Сводка по группе"), header_style="bold")
    cols = [
        (pick(lang, "Student", "Студент"), "student", "{}"),
        (pick(lang, "Var.", "Вар."), "variant", "{}"),
        ("n_d", "n_motor_rpm", "{:.0f}"),
        ("i_pl", "i_planetary", "{:.3f}"),
        (pick(lang, "Scheme", "Схема"), "planetary_scheme", "{}"),
        (pick(lang, "Teeth", "Зубья"), "teeth", "{}"),
        ("k", "planets", "{}"),
        ("z1/z2", None, "{}"),
        ("ε_α", "eps_alpha", "{:.3f}"),
        ("r0, mm", "r0_mm", "{:.2f}"),
        ("e / l_OC, mm", None, "{:.2f}"),
        ("ν_у/ν_в, °", None, "{:.1f}"),
        ("⚠", "warnings", "{}"),
    ]
    for head, _, _ in cols:
        t.add_column(head, justify="right" if head not in (pick(lang, "Student", "Студент"),) else "left")
    for r in summary.rows:
        if r["status"] != "ok":
            t.add_row(str(r["student"]), str(r["variant"] or "—"), f"[red]{pick(lang, 'failed', 'ошибка')}: {r['error']}[/]", *[""] * (len(cols) - 3))
            continue
        cells = []
        for head, key, fmt in cols:
            if head == "z1/z2":
                cells.append(f"{r['z1']}/{r['z2']}")
            elif head.startswith("e / l_OC"):
                val = r["e_mm"] if r.get("e_mm") not in (None, "") else r["l_oc_mm"]
                cells.append(_cell(val, fmt))
            elif head.startswith("ν_у"):
                ret = r.get("nu_return_deg")
                cells.append(f"{_cell(r['nu_rise_deg'], fmt)}/{_cell(ret, fmt)}")
            else:
                cells.append(_cell(r[key], fmt))
        t.add_row(*cells)
    console.print(t)
    ok = len(summary.rows) - len(summary.failed)
    console.print(pick(lang, f"{ok} done, {len(summary.failed)} failed; summary: {Path(out_dir) / 'summary.csv'}",
                       f"выполнено {ok}, с ошибкой {len(summary.failed)}; сводка: {Path(out_dir) / 'summary.csv'}"))
