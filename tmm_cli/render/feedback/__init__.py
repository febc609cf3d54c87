"""Feedback to a student after `tmm check`: ``check-<name>.md`` (and its PDF) that reads as a
teacher's remarks — what is wrong, by how much, the likely cause and where the book explains it —
and the group's ``check.md``.

A report is a :class:`tmm_cli.teacher.rows.CheckReport`, read by its fields. The document is built
once (render/note's :class:`~tmm_cli.render.note.doc.Doc`) and written as Markdown and as typst.
"""

from __future__ import annotations

from pathlib import Path

from ...i18n.lang import note_text, pick
from ...i18n.numbers import num, plural
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
    """A student's own text inside the document: a '$' never opens typst math."""
    return str(text).replace("$", "\uff04")


def student_doc(report, lang: str):
    """The feedback as a document: the verdict, what to correct, remarks, what is right, the table."""
    from ..note.doc import Doc

    doc = Doc(lang)
    rows = report.rows
    good = [r for r in rows if passed(r)]
    bad = [r for r in rows if not passed(r)]
    facts = [pick(lang, f"Variant {report.variant}", f"Вариант {report.variant}")]
    if report.group:
        facts.append(pick(lang, "group ", "группа ") + _plain(report.group))
    facts.append(pick(lang, "tolerance ", "допуск ") + f"{num(report.rtol_pct, lang, sig=3, sci=False)} %")
    if report.answers_file:
        facts.append(pick(lang, "answers file ", "файл ответов ") + _plain(report.answers_file))
    doc.p("; ".join(facts) + ".")
    if report.error:
        from ...i18n.help_ru import error_text

        doc.p(pick(lang, "The answers could not be checked: ", "Ответы не удалось проверить: ")
              + _plain(error_text(report.error, lang)))
        return doc
    verdict = pick(lang, "PASSED", "ЗАЧТЕНО") if report.passed else pick(lang, "NOT PASSED", "НЕ ЗАЧТЕНО")
    doc.p(pick(lang, f"Verdict: {verdict} — {len(good)} of {len(rows)} values right.",
               f"Итог: {verdict} — верно {len(good)} из {len(rows)}."))
    for note in report.notes:
        doc.p(note_text(note, lang))
    if bad:
        doc.h(2, pick(lang, "What to correct", "Что исправить"), numbered=False)
        doc.items([_plain(row_sentence(r, lang)) for r in bad])
    if report.findings:
        doc.h(2, pick(lang, "Remarks", "Замечания"), numbered=False)
        doc.items([_plain(t) for t in findings_lines(report.findings, lang)])
    if good:
        doc.h(2, pick(lang, "Right", "Верно"), numbered=False)
        doc.items([_plain(row_sentence(r, lang)) for r in good])
    header = [pick(lang, "Value", "Величина"), pick(lang, "Yours", "Ваш ответ"), pick(lang, "Right", "Верно"),
              pick(lang, "Deviation", "Отклонение"), pick(lang, "Tolerance", "Допуск"), pick(lang, "Result", "Итог"),
              pick(lang, "Where to look", "Где смотреть")]
    body = [[_plain(symbol(r.key, lang) if r.status != "unknown key" else r.written or r.key),
             _plain(value_text(r.given, r.key, lang)), value_text(r.expected, r.key, lang), deviation_text(r, lang),
             tolerance_text(r, lang), status_word(r.status, lang), place_text(r.place, lang)] for r in rows]
    doc.table("values", pick(lang, "Every checked value", "Все проверенные величины"), header, body,
              align="left, right, right, right, left, left, left")
    return doc


def _title(report, lang: str) -> str:
    return pick(lang, f"Check: {report.label}", f"Проверка: {report.label}")


def student_markdown(report, lang: str) -> str:
    """check-<name>.md."""
    return student_doc(report, lang).to_markdown(_plain(_title(report, lang)))


_TYPST_HEAD = """// Feedback written by `tmm check`.
#set document(title: {title})
#set page(paper: "a4", margin: (left: 20mm, right: 15mm, top: 15mm, bottom: 15mm))
#set text(font: ("Times New Roman", "Liberation Serif", "Libertinus Serif"), size: 11pt, lang: "{lang}")
#set par(justify: false, spacing: 0.8em)
#set table(stroke: 0.4pt, inset: 3pt)
#show table: set text(size: 8.5pt)
#show figure.caption: set align(left)
#text(size: 14pt, weight: "bold")[{title_markup}]
"""


def student_typst(report, lang: str) -> str:
    """The same feedback as typst source (compiled to check-<name>.pdf)."""
    from ..note.doc import typst_escape, typst_string

    title = _plain(_title(report, lang))
    head = _TYPST_HEAD.format(title=typst_string(title), lang="ru" if lang == "ru" else "en",
                              title_markup=typst_escape(title))
    return student_doc(report, lang).to_typst(head)


def write_feedback(folder: Path, reports, lang: str, pdf: bool = False) -> list[str]:
    """check-<name>.md (and .pdf) of every report that has a student file name, into `folder`
    (a staging folder); the names written."""
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
    title = pick(lang, "Group check", "Проверка группы")
    lines = [f"# {title}", "",
             pick(lang, f"Tolerance {num(rtol_pct, lang)} %, sheets {', '.join(sorted(sheets))}; passed {n_pass} of {len(group.reports)}.",
                  f"Допуск {num(rtol_pct, lang)} %, листы {', '.join(sorted(sheets))}; зачтено {n_pass} из {len(group.reports)}."), ""]
    if group.roster_encoding:
        lines += [pick(lang, f"Roster read as {group.roster_encoding}.", f"Список прочитан в кодировке {group.roster_encoding}."), ""]
    lines.append("| " + " | ".join(cell(h) for h in header) + " |")
    lines.append("|" + "---|" * len(header))
    for row in body:
        lines.append("| " + " | ".join(cell(v) for v in row) + " |")
    if group.unmatched:
        lines += ["", "## " + pick(lang, "Answers files of nobody on the roster", "Файлы ответов, не найденные в списке"), ""]
        for f, near in group.unmatched:
            hint = pick(lang, f" (like {near}?)", f" (возможно, {near}?)") if near else ""
            lines.append(f"- {cell(f)}{cell(hint)}")
    feedback = [rep for rep in group.reports if getattr(rep, "fname", "")]
    if feedback:
        lines += ["", pick(lang, f"Each student's feedback: {FEEDBACK_DIR}/check-<name>.md.",
                           f"Замечания каждому студенту: {FEEDBACK_DIR}/check-<имя>.md."),
                  plural(len(feedback), lang, {"one": "file", "other": "files"} if lang != "ru" else
                         {"one": "файл", "few": "файла", "many": "файлов", "other": "файла"}) + "."]
    return "\n".join(lines) + "\n"
