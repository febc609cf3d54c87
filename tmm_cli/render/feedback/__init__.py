"""Feedback to a student after `tmm check`: ``check-<name>.md`` (and its PDF) that reads as a
teacher's remarks — what is wrong, by how much, the likely cause and where the book explains it —
and the group's ``check.md``.

A report is a :class:`tmm_cli.teacher.rows.CheckReport`, read by its fields. The document is built
once (render/note's :class:`~tmm_cli.render.note.doc.Doc`) and written as Markdown and as typst.
"""

from __future__ import annotations

from pathlib import Path

from ...i18n import ntr, tr, trc
from ...i18n.lang import note_text
from ...i18n.numbers import num
from .words import (
    deviation_text,
    findings_lines,
    passed,
    place_text,
    row_sentence,
    status_word,
    symbol,
    tolerance_text,
    value_text,
)

FEEDBACK_DIR = "feedback"


def feedback_name(fname: str, ext: str = "md") -> str:
    """check-Иванов_И._И.md: the feedback file of a student (`fname`: names.file_name)."""
    return f"check-{fname}.{ext}"


def _plain(text: str) -> str:
    """A student's own text (or a sentence holding it) inside the document: set as the characters
    given, never as markup (render/note/model.literal)."""
    from ..note.model import literal

    return literal(str(text))


def student_doc(report, lang: str):
    """The feedback as a document: the verdict, what to correct, remarks, what is right, the table."""
    from ..note.doc import Doc

    doc = Doc(lang)
    rows = report.rows
    good = [r for r in rows if passed(r)]
    bad = [r for r in rows if not passed(r)]
    facts = [tr(lang, 'Variant {variant}').format(variant=report.variant)]
    if report.group:
        facts.append(tr(lang, 'group ') + _plain(report.group))
    facts.append(tr(lang, 'tolerance ') + f"{num(report.rtol_pct, lang, sig=3, sci=False)} %")
    if report.answers_file:
        facts.append(tr(lang, 'answers file ') + _plain(report.answers_file))
    doc.p("; ".join(facts) + ".")
    if report.error:
        from ...i18n.errors import error_text

        doc.p(tr(lang, 'The answers could not be checked: ')
              + _plain(error_text(report.error, lang)))
        return doc
    verdict = tr(lang, 'PASSED') if report.passed else tr(lang, 'NOT PASSED')
    doc.p(tr(lang, 'Verdict: {verdict} — {good} of {total} values right.').format(verdict=verdict, good=len(good), total=len(rows)))
    for note in report.notes:
        doc.p(note_text(note, lang))
    if bad:
        doc.h(2, tr(lang, 'What to correct'), numbered=False)
        doc.items([_plain(row_sentence(r, lang)) for r in bad])
    if report.findings:
        doc.h(2, tr(lang, 'Remarks'), numbered=False)
        doc.items([_plain(t) for t in findings_lines(report.findings, lang)])
    if good:
        doc.h(2, tr(lang, 'Right'), numbered=False)
        doc.items([_plain(row_sentence(r, lang)) for r in good])
    header = [trc(lang, "check", "Value"), tr(lang, 'Yours'), tr(lang, 'Right'),
              tr(lang, 'Deviation'), tr(lang, 'Tolerance'), tr(lang, 'Result'),
              tr(lang, 'Where to look')]
    body = [[_plain(symbol(r.key, lang) if r.status != "unknown key" else r.written or r.key),
             _plain(value_text(r.given, r.key, lang)), value_text(r.expected, r.key, lang), deviation_text(r, lang),
             tolerance_text(r, lang), status_word(r.status, lang), place_text(r.place, lang)] for r in rows]
    doc.table("values", tr(lang, 'Every checked value'), header, body,
              align="left, right, right, right, left, left, left")
    return doc


def _title(report, lang: str) -> str:
    return tr(lang, 'Check: {student}').format(student=report.label)


def student_markdown(report, lang: str) -> str:
    """check-<name>.md."""
    from ..note.model import md_text

    return student_doc(report, lang).to_markdown(md_text(_title(report, lang)))


_TYPST_HEAD = """// Feedback written by `tmm check`.
#set document(title: {title})
#set page(paper: "a4", margin: (left: 20mm, right: 15mm, top: 15mm, bottom: 15mm))
#set text(font: "Liberation Serif", size: 11pt, lang: "{lang}")
#set par(justify: false, spacing: 0.8em)
#set table(stroke: 0.4pt, inset: 3pt)
#show table: set text(size: 8.5pt)
#show figure.caption: set align(left)
#text(size: 14pt, weight: "bold")[{title_markup}]
"""


def student_typst(report, lang: str) -> str:
    """The same feedback as typst source (compiled to check-<name>.pdf)."""
    from ..note.doc import typst_string
    from ..note.typst import literal_text

    title = _title(report, lang)
    head = _TYPST_HEAD.format(title=typst_string(title), lang="ru" if lang == "ru" else "en",
                              title_markup=literal_text(title))
    return student_doc(report, lang).to_typst(head)


def write_feedback(folder: Path, reports, lang: str, pdf: bool = False, failed: list | None = None) -> list[str]:
    """check-<name>.md (and .pdf) of every report that has a student file name, into `folder`
    (a staging folder); the names written. A PDF typst cannot set (past its time or memory
    limit) is left out, its Markdown kept, and (name, error) appended to `failed`: one student's
    text never stops the others' feedback (without `failed`, the error is raised)."""
    from ...errors import TmmError

    folder = Path(folder)
    written = []
    for rep in reports:
        if not getattr(rep, "fname", ""):
            continue
        name = feedback_name(rep.fname)
        (folder / name).write_text(student_markdown(rep, lang), encoding="utf-8")
        written.append(name)
        if pdf:
            from ..note import compile_note

            src = feedback_name(rep.fname, "typ")
            (folder / src).write_text(student_typst(rep, lang), encoding="utf-8")
            try:
                compile_note(folder, src, feedback_name(rep.fname, "pdf"))
            except TmmError as exc:
                if failed is None:
                    raise
                failed.append((feedback_name(rep.fname, "pdf"), str(exc)))
                continue
            finally:
                (folder / src).unlink(missing_ok=True)
            written.append(feedback_name(rep.fname, "pdf"))
    return written


def group_markdown(group, lang: str, rtol_pct: float, sheets, table) -> str:
    """check.md: the group's verdicts as a Markdown table (`table`: header and rows, see
    render/terminal/check.group_table), the files that matched no student, readable as it is."""
    from ..data.csv import safe_cell

    def cell(v) -> str:
        return safe_cell(v).replace("|", "\\|").replace("*", "\\*").replace("_", "\\_").replace("`", "\\`") \
            .replace("<", "&lt;").replace(">", "&gt;").replace("[", "\\[")

    header, body = table
    n_pass = sum(rep.passed for rep in group.reports)
    title = tr(lang, 'Group check')
    lines = [f"# {title}", "",
             tr(lang, 'Tolerance {tol} %, sheets {sheets}; passed {n_pass} of {total}.').format(tol=num(rtol_pct, lang), sheets=', '.join(sorted(sheets)), n_pass=n_pass, total=len(group.reports)), ""]
    if group.roster_encoding:
        lines += [tr(lang, 'Roster read as {encoding}.').format(encoding=group.roster_encoding), ""]
    lines.append("| " + " | ".join(cell(h) for h in header) + " |")
    lines.append("|" + "---|" * len(header))
    for row in body:
        lines.append("| " + " | ".join(cell(v) for v in row) + " |")
    if group.unmatched:
        lines += ["", "## " + tr(lang, 'Answers files of nobody on the roster'), ""]
        for f, near in group.unmatched:
            hint = tr(lang, ' (like {near}?)').format(near=near) if near else ""
            lines.append(f"- {cell(f)}{cell(hint)}")
    feedback = [rep for rep in group.reports if getattr(rep, "fname", "")]
    if feedback:
        lines += ["", tr(lang, "Each student's feedback: {folder}/check-<name>.md.").format(folder=FEEDBACK_DIR),
                  ntr(lang, "{n} file.", "{n} files.", len(feedback)).format(n=len(feedback))]
    return "\n".join(lines) + "\n"
