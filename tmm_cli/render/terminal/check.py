"""Rich tables for `tmm check`: one student's comparison with what to correct, a group's verdicts,
the answer keys."""

from __future__ import annotations

from ...i18n import tr
from ...i18n.numbers import num
from ..feedback.words import (
    STATUS,  # noqa: F401  (the verdict words, for callers that list them)
    deviation_text,
    passed,
    place_text,
    row_sentence,
    status_word,
    symbol,
    tolerance_text,
    value_text,
)

_COLOUR = {"fail": "red", "missing": "red", "unreadable": "red", "duplicate": "red", "unknown key": "yellow",
           "not checked": "yellow", "not computed": "yellow"}


def _coloured(status: str, lang: str) -> str:
    from . import escape

    colour = "green" if status.startswith("pass") else _COLOUR.get(status, "yellow")
    return f"[{colour}]{escape(status_word(status, lang))}[/]"


def print_keys(console, lang: str, keys, required: dict) -> None:
    """`tmm check --keys`: the answer keys `keys` (AnswerKey records), the names a student may write
    them under, and the sheet that requires each (`required`: sheet -> its keys)."""
    from rich.table import Table

    t = Table(title=tr(lang, "Answer keys for `tmm check`"), header_style="bold")
    t.add_column(tr(lang, "Key"))
    t.add_column(tr(lang, "Also written"))
    t.add_column(tr(lang, "Compared"))
    t.add_column(tr(lang, "Required"))
    t.add_column(tr(lang, "Meaning"))
    for k in keys:
        sheet = next((s for s, names in required.items() if k.key in names), "")
        req = tr(lang, "sheet {sheet}").format(sheet=sheet) if sheet else "—"
        how = {"int": tr(lang, "exact"), "input": tr(lang, "Table 1.2")}.get(
            k.kind, tr(lang, "within tolerance"))
        t.add_row(k.key, ", ".join(k.aliases[:4]), how, req, tr(lang, k.meaning))
    console.print(t)
    console.print(tr(lang, "A required key is needed when the variant computes it (z_planet2: scheme 2; *_2: a two-stage reducer; e_mm: translating follower; l_oc_mm: rocker); a missing one fails the check. --sheet 3 or --sheet 4 checks one sheet. A key may be written as in the book (r_0, z_1, u_1H, φ_у …); a misspelt one gets a suggestion."))
    console.print(tr(lang, "TOML example:  r0_mm = 41.5   z_sun = 40   eps_alpha = 1.58"))


def _who(report, lang: str) -> str:
    return "" if report.label == f"variant {report.variant}" else f"{report.label}, "


def print_check(console, report, lang: str) -> None:
    """One student: every checked value (yours, right, deviation, tolerance, result, where to look),
    then what to correct in sentences, the remarks and the verdict."""
    from . import escape
    from rich.table import Table

    from ...i18n.lang import note_text

    who = escape(_who(report, lang))
    tol = num(report.rtol_pct, lang)
    t = Table(title=tr(lang, "Check — {who}variant {variant}, tolerance {tol} %").format(
        who=who, variant=report.variant, tol=tol),
              header_style="bold")
    heads = (tr(lang, "Value"), tr(lang, "Yours"), tr(lang, "Right"),
             tr(lang, "Deviation"), tr(lang, "Tolerance"), tr(lang, "Result"),
             tr(lang, "Where to look"))
    for i, head in enumerate(heads):
        t.add_column(head, justify="right" if i in (1, 2, 3) else "left", overflow="fold")
    for r in report.rows:
        name = symbol(r.key, lang) if r.status != "unknown key" else (r.written or r.key)
        if r.written and r.written not in (r.key, name) and r.status != "unknown key":
            name += f" ({r.written})"
        t.add_row(escape(name), escape(value_text(r.given, r.key, lang)), value_text(r.expected, r.key, lang),
                  deviation_text(r, lang), tolerance_text(r, lang), _coloured(r.status, lang), place_text(r.place, lang))
    console.print(t)
    for note in report.notes:
        console.print(f"[cyan]ℹ[/] {escape(note_text(note, lang))}")
    bad = [r for r in report.rows if not passed(r)]
    if bad:
        console.print(tr(lang, "[bold]What to correct[/]"))
        for r in bad:
            console.print(f"  [red]✘[/] {escape(row_sentence(r, lang))}")
    remarks = [r for r in report.rows if passed(r) and r.status != "pass" and r.cause is not None]
    from ..feedback.words import findings_lines

    for line in findings_lines(report.findings, lang):
        console.print(f"  [cyan]ℹ[/] {escape(line)}")
    for r in remarks:
        if not any(r.cause == n for n in report.findings):
            console.print(f"  [green]✔[/] {escape(row_sentence(r, lang))}")
    n_pass = sum(passed(r) for r in report.rows)
    verdict = (tr(lang, "[green]PASSED[/]") if report.passed
               else tr(lang, "[red]NOT PASSED[/]"))
    console.print(tr(lang, "Verdict: {verdict} ({n_pass} of {rows} values correct)").format(verdict=verdict, n_pass=n_pass, rows=len(report.rows)))


def _verdict(rep, lang: str) -> str:
    if rep.error:
        return tr(lang, "error")
    return tr(lang, "passed") if rep.passed else tr(lang, "not passed")


def group_table(group, lang: str) -> tuple[list[str], list[list]]:
    """The rows of check.md: one per student, the verdict and the result of every key."""
    keys = group.keys()
    header = [tr(lang, "student"), tr(lang, "group"), tr(lang, "variant"),
              tr(lang, "verdict"), tr(lang, "correct"), tr(lang, "of")] + keys + [
              tr(lang, "missing"), tr(lang, "error")]
    body = []
    from ...i18n.errors import error_text

    for rep in group.reports:
        by = {r.key: r.status for r in rep.rows}
        good = sum(passed(r) for r in rep.rows)
        body.append([rep.label, rep.group, rep.variant or "", _verdict(rep, lang), good if not rep.error else "",
                     len(rep.rows) if not rep.error else ""]
                    + [status_word(by[k], lang) if k in by else "" for k in keys]
                    + [" ".join(rep.missing), error_text(rep.error, lang) if rep.error else ""])
    return header, body


def group_markdown(group, lang: str, rtol_pct: float, sheets) -> str:
    """check.md (see render/feedback.group_markdown)."""
    from ..feedback import group_markdown as md

    return md(group, lang, rtol_pct, sheets, group_table(group, lang))


def print_group(console, group, lang: str) -> None:
    from . import escape
    from rich.table import Table

    from ...i18n.errors import error_text

    t = Table(title=tr(lang, "Group check"), header_style="bold")
    for head in (tr(lang, "Student"), tr(lang, "Variant"), tr(lang, "Correct"),
                 tr(lang, "Wrong or missing"), tr(lang, "Verdict")):
        t.add_column(head)
    for rep in group.reports:
        if rep.error:
            t.add_row(escape(rep.label), str(rep.variant or "—"), "—", "—", f"[red]{escape(error_text(rep.error, lang))}[/]")
            continue
        good = sum(passed(r) for r in rep.rows)
        wrong = ", ".join((symbol(r.key, lang) if r.status != "unknown key" else (r.written or r.key))
                          + (tr(lang, " (missing)") if r.status == "missing" else "")
                          for r in rep.rows if not passed(r)) or "—"
        verdict = tr(lang, "[green]passed[/]") if rep.passed else tr(lang, "[red]not passed[/]")
        t.add_row(escape(rep.label), str(rep.variant), f"{good}/{len(rep.rows)}", escape(wrong), verdict)
    console.print(t)
    for f, near in group.unmatched:
        hint = tr(lang, " — perhaps {near}?").format(near=near) if near else ""
        console.print("[yellow]![/] " + escape(tr(lang, "Answers file {f} matches no student on the roster").format(f=f) + hint))
