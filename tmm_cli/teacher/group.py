"""The group's page (group.html) and the files of a group check, from what `tmm batch` and
`tmm check` know: a batch's summary rows, a check's reports, and the files either wrote into the
same folder (a batch's notes and sheets, a check's feedback), so that the page of the one links
what the other wrote.

Every link points to a file this program wrote (listed in its folder's manifest) that exists.
"""

from __future__ import annotations

import datetime as _dt
import json

import os
from pathlib import Path

from ..i18n import N_, tr

from ..i18n.numbers import num

GROUP_FILES = ("check.csv", "check.md", "check.json", "group.html")
PAGE = "group.html"
STUDENT_FILES = (("note.pdf", N_("note")), ("sheet3.pdf", N_("sheet 3")), ("sheet4.pdf", N_("sheet 4")),
                 ("report.md", N_("report")), ("results.json", "JSON"))


# links -------------------------------------------------------------------------------------------


def written_files(out_dir: Path, rel: str, names) -> list[str]:
    """Of `names` in the folder out_dir/rel, those this program wrote that exist as regular files
    (relative paths with '/')."""
    from ..output.folder import read_manifest

    folder = Path(out_dir) / rel if rel else Path(out_dir)
    if not folder.is_dir() or folder.is_symlink():
        return []
    ours = read_manifest(folder)["files"]
    out = []
    for name in names:
        p = folder / name
        if name in ours and p.is_file() and not p.is_symlink():
            out.append(f"{rel}/{name}" if rel else name)
    return out


def _student_links(out_dir: Path, rel: str | None, lang: str, feedback: list[str]) -> tuple:
    from ..render.html.group import PageLink

    links = []
    if rel:
        names = [n for n, _ in STUDENT_FILES]
        found = set(written_files(out_dir, rel, names))
        for name, label in STUDENT_FILES:
            if f"{rel}/{name}" in found:
                links.append(PageLink(tr(lang, label), f"{rel}/{name}"))
    for f in feedback:
        links.append(PageLink(tr(lang, "feedback") + (" (PDF)" if f.endswith(".pdf") else ""), f))
    return tuple(links)


def _feedback_files(out_dir: Path, fname: str) -> list[str]:
    from ..render.feedback import FEEDBACK_DIR, feedback_name

    if not fname:
        return []
    return written_files(out_dir, FEEDBACK_DIR, [feedback_name(fname, "md"), feedback_name(fname, "pdf")])


def _rel_folder(out_dir: Path, folder) -> str | None:
    """A batch row's folder relative to the page, '/'-separated; None if it is not inside."""
    if not folder:
        return None
    try:
        rel = os.path.relpath(str(folder), str(out_dir))
    except ValueError:  # another drive (Windows)
        return None
    if rel.startswith("..") or os.path.isabs(rel):
        return None
    return rel.replace(os.sep, "/")


# the check's cells ---------------------------------------------------------------------------------


def _check_cells(rep, keys, lang):
    """One cell per key: the deviation in per cent (a number within tolerance) or the answer
    (a whole number), coloured by the verdict; its title is the feedback sentence."""
    from ..render.feedback.words import passed, row_sentence, status_word
    from ..render.html.group import PageCell

    by = {r.key: r for r in rep.rows}
    cells = []
    for k in keys:
        r = by.get(k)
        if r is None:
            cells.append(PageCell("", sort=None))
            continue
        level = "good" if passed(r) else ("warn" if r.status in ("unknown key", "not computed", "not checked") else "bad")
        if r.status.startswith("pass") and r.status != "pass":
            level = "warn" if r.status == "pass (book roller, undercuts)" else "good"
        if (passed(r) or r.status == "fail") and r.tolerance_pct is not None and r.deviation_pct is not None:
            text = ("−" if r.deviation_pct < 0 else "+") + num(abs(r.deviation_pct), lang, decimals=1) + " %"
            sort = abs(r.deviation_pct)
        elif r.status in ("missing", "unreadable", "duplicate", "not checked", "unknown key"):
            text, sort = status_word(r.status, lang), 1e9
        else:
            text = "" if r.given is None else (str(r.given) if not isinstance(r.given, float) else num(r.given, lang, sig=5))
            sort = 0 if passed(r) else 1e6
        cells.append(PageCell(text, level, sort, row_sentence(r, lang)))
    return cells


def _check_stats(group, keys, lang):
    from ..render.feedback.words import passed, symbol
    from ..render.html.group import Stat

    stats = [Stat(tr(lang, "passed the check"), sum(r.passed for r in group.reports),
                  len(group.reports))]
    for k in keys:
        rows = [r for rep in group.reports for r in rep.rows if r.key == k]
        if rows:
            stats.append(Stat(symbol(k, lang), sum(passed(r) for r in rows), len(rows)))
    return stats


def _check_charts(group, lang):
    from ..render.html.group import Chart

    r0 = [r.deviation_pct for rep in group.reports for r in rep.rows
          if r.key == "r0_mm" and r.status in ("pass", "fail") and r.deviation_pct is not None]
    tol = group.reports[0].rtol_pct if group.reports else 3.0
    sets = [rep.set_ratio_error_pct for rep in group.reports if rep.set_ratio_error_pct is not None]
    ratio_tol = next((rep.ratio_tolerance_pct for rep in group.reports if rep.rows), 5.0)
    return [Chart(tr(lang, "Deviation of r_0 from the right value"), tuple(r0), "%", tol),
            Chart(tr(lang, "Ratio error of the students' tooth sets"),
                  tuple(sets), "%", ratio_tol)]


def _verdict_cell(rep, lang):
    from ..render.html.group import PageCell

    if rep.error:
        return PageCell(tr(lang, "error"), "bad", 2), "error"
    if rep.passed:
        return PageCell(tr(lang, "passed"), "good", 0), "passed"
    return PageCell(tr(lang, "not passed"), "bad", 1), "not passed"


# pages -------------------------------------------------------------------------------------------


def _today(lang: str) -> str:
    d = _dt.date.today()
    return d.strftime("%d.%m.%Y") if lang == "ru" else d.isoformat()


def check_page(out_dir: Path, group, lang: str, rtol_pct: float, sheets):
    """The page of a group check: a row per student with every key's deviation coloured, links to
    the feedback and, where a batch wrote them into the same folder, to the note and sheets."""
    from ..render.feedback.words import symbol
    from ..render.html.group import GroupPage, PageCell, PageRow

    keys = group.keys()
    columns = [(tr(lang, "Student"), False), (tr(lang, "Group"), False),
               (tr(lang, "Var."), True), (tr(lang, "Verdict"), False),
               (tr(lang, "Right"), True)] + [(symbol(k, lang), True) for k in keys]
    rows = []
    for rep in group.reports:
        verdict, status = _verdict_cell(rep, lang)
        good = sum(r.passed for r in rep.rows)
        cells = [PageCell(rep.label), PageCell(rep.group), PageCell(str(rep.variant or ""), sort=rep.variant or 0), verdict,
                 PageCell(f"{good}/{len(rep.rows)}" if rep.rows else "—", sort=good)]
        cells += _check_cells(rep, keys, lang) if not rep.error else [PageCell("") for _ in keys]
        rel = f"{rep.fname}/variant-{rep.variant:02d}" if rep.fname and rep.variant else None
        links = _student_links(out_dir, rel, lang, _feedback_files(out_dir, rep.fname))
        detail = ""
        if rep.error:
            from ..i18n.errors import error_text

            detail = error_text(rep.error, lang)
        elif rep.findings:
            from ..render.feedback.words import findings_lines

            detail = " ".join(findings_lines(rep.findings, lang))
        rows.append(PageRow(status, tuple(cells), links, detail))
    remarks = [tr(lang, "Answers file {f} matches no student on the roster").format(f=f) + (tr(lang, " (perhaps {n}?)").format(n=n) if n else "")
               for f, n in group.unmatched]
    n_pass = sum(r.passed for r in group.reports)
    subtitle = tr(lang, "Tolerance {rtol_pct} %, sheets {sheets}; passed {n_pass} of {reports}; {today}. Hover a cell for the feedback on it.").format(rtol_pct=num(rtol_pct, lang), sheets=', '.join(sorted(sheets)), n_pass=n_pass, reports=len(group.reports), today=_today(lang))
    statuses = (("passed", tr(lang, "passed")), ("not passed", tr(lang, "not passed")),
                ("error", tr(lang, "error")))
    return GroupPage(lang, tr(lang, "Group check"), subtitle, tuple(columns), tuple(rows), statuses,
                     tuple(_check_stats(group, keys, lang)), tuple(_check_charts(group, lang)), tuple(remarks))


def _flag_level(row: dict, flag: str) -> str:
    return "bad" if flag in (row.get("warnings") or ()) else ""


def batch_page(out_dir: Path, rows: list[dict], lang: str, tolerance_pct: float | None = None, check: dict | None = None):
    """The page of a batch: a row per student with the key numbers of both sheets, the warnings in
    words, links to the note, the sheets, the report; with a check of the same folder (check.json)
    also each student's verdict and feedback."""
    from ..render.data.summary import STATUS, flag_name
    from ..render.html.group import Chart, GroupPage, PageCell, PageRow, Stat

    checked = {}
    if check:
        for s in check.get("students", []):
            checked[(str(s.get("student")), str(s.get("variant")))] = s
    columns = [(tr(lang, "Student"), False), (tr(lang, "Group"), False),
               (tr(lang, "Var."), True), (tr(lang, "Status"), False),
               (tr(lang, "n_d, rpm"), True), ("i_pl" if lang != "ru" else "i_пл", True),
               (tr(lang, "teeth × k"), False), (tr(lang, "ratio error, %"), True),
               ("z1/z2", False), ("ε_α", True), (tr(lang, "r_0, mm"), True),
               (tr(lang, "e or l_OC, mm"), True), (tr(lang, "ν_rise/ν_ret, °"), False),
               (tr(lang, "Warnings"), False)]
    if checked:
        columns.append((tr(lang, "Check"), False))
    out = []
    tol = tolerance_pct if tolerance_pct is not None else 5.0

    def n(v, d=2):
        if v is None or v == "":
            return PageCell("—")
        return PageCell(num(float(v), lang, decimals=d), sort=float(v))

    for r in rows:
        st = r.get("status", "")
        label = tr(lang, STATUS.get(st, st))
        level = "good" if st == "ok" else ("bad" if st == "failed" else "warn")
        lead = [PageCell(str(r.get("student", ""))), PageCell(str(r.get("group", ""))),
                PageCell(str(r.get("variant", "")), sort=_int(r.get("variant"))), PageCell(label, level)]
        if st != "ok":
            cells = lead + [PageCell("") for _ in columns[4:]]
        else:
            err = r.get("ratio_error_pct")
            err_cell = n(err)
            if err not in (None, ""):
                big = abs(float(err)) > tol + 1e-9
                err_cell = PageCell(err_cell.text, "bad" if big else ("warn" if abs(float(err)) > 3.0 else "good"), abs(float(err)))
            eps = r.get("eps_alpha")
            eps_cell = n(eps, 3)
            if eps not in (None, ""):
                eps_cell = PageCell(eps_cell.text, "warn" if float(eps) < 1.2 else "", float(eps))
            other = r.get("e_mm") if r.get("e_mm") not in (None, "") else r.get("l_oc_mm")
            nu = n(r.get("nu_rise_deg"), 1).text + "/" + n(r.get("nu_return_deg"), 1).text
            words = ", ".join(flag_name(f, lang) for f in (r.get("warnings") or ()))
            cells = lead + [n(r.get("n_motor_rpm"), 0), n(r.get("i_planetary"), 3),
                            PageCell(f"{r.get('teeth', '')} × {r.get('planets', '')}"), err_cell,
                            PageCell(f"{r.get('z1', '')}/{r.get('z2', '')}", "warn" if _flag_level(r, "undercut") else ""),
                            eps_cell, n(r.get("r0_mm")), n(other),
                            PageCell(nu, "bad" if _flag_level(r, "pressure_angle") else ""),
                            PageCell(words or "—", "warn" if words else "")]
        status = {"ok": "ok", "failed": "failed"}.get(st, "not run")
        fname = ""
        if checked:
            s = checked.get((str(r.get("student")), str(r.get("variant"))))
            if s is None:
                cells.append(PageCell("—"))
            else:
                fname = s.get("file_name") or ""
                if s.get("error"):
                    cells.append(PageCell(tr(lang, "error"), "bad", 2))
                elif s.get("passed"):
                    cells.append(PageCell(tr(lang, "passed"), "good", 0))
                else:
                    wrong = [x["key"] for x in s.get("rows", []) if not str(x.get("status", "")).startswith("pass")]
                    cells.append(PageCell(tr(lang, "not passed"), "bad", 1, ", ".join(wrong)))
        rel = _rel_folder(out_dir, r.get("folder")) if st == "ok" else None
        links = _student_links(out_dir, rel, lang, _feedback_files(out_dir, fname))
        detail = ""
        if st != "ok" and r.get("error"):
            from ..i18n.errors import error_text

            detail = error_text(str(r["error"]), lang)
        out.append(PageRow(status, tuple(cells), links, detail))
    ok = [r for r in rows if r.get("status") == "ok"]
    stats = [Stat(tr(lang, "computed"), len(ok), len(rows))]
    for flag, label in (("ratio_error", N_("ratio within tolerance")), ("undercut", N_("no undercut")),
                        ("pressure_angle", N_("pressure angle within ν_max")), ("contact_ratio", N_("contact ratio enough"))):
        stats.append(Stat(tr(lang, label), sum(1 for r in ok if flag not in (r.get("warnings") or ())), len(ok)))
    if checked:
        students = check.get("students", [])
        stats.append(Stat(tr(lang, "passed the check"), sum(1 for s in students if s.get("passed")),
                          len(students)))
    charts = [Chart(tr(lang, "Base radius r_0 of the group"),
                    tuple(float(r["r0_mm"]) for r in ok if r.get("r0_mm") not in (None, "")), tr(lang, "mm")),
              Chart(tr(lang, "Ratio error of the reducers"),
                    tuple(float(r["ratio_error_pct"]) for r in ok if r.get("ratio_error_pct") not in (None, "")), "%", tol)]
    n_ok = len(ok)
    subtitle = tr(lang, "{n_ok} of {rows} computed; {today}.").format(n_ok=n_ok, rows=len(rows), today=_today(lang))
    statuses = tuple((code, tr(lang, STATUS[code])) for code in ("ok", "failed", "not run"))
    return GroupPage(lang, tr(lang, "The group at a glance"), subtitle, tuple(columns), tuple(out),
                     statuses, tuple(stats), tuple(charts))


def _int(v):
    try:
        return int(v)
    except (TypeError, ValueError):
        return 0


def read_check_json(out_dir: Path) -> dict | None:
    """check.json of a group check written into `out_dir` (None when there is none of ours)."""
    from ..output.folder import read_manifest

    p = Path(out_dir) / "check.json"
    if "check.json" not in read_manifest(out_dir)["files"] or not p.is_file() or p.is_symlink():
        return None
    try:
        if p.stat().st_size > 16 << 20:
            return None
        data = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, ValueError, RecursionError):
        return None
    return data if isinstance(data, dict) else None


def write_group_check(out_dir: Path, group, lang: str, csv_locale: str, rtol_pct: float, sheets, *, pdf: bool = False,
                      feedback: bool = True, kept: list | None = None, failed: list | None = None) -> list[str]:
    """The files of a group check: feedback/check-<name>.md (.pdf), check.csv, check.md, check.json
    and group.html, each written atomically and recorded as ours. Returns the names written (a file
    the teacher changed since is kept and the new one written beside it: appended to `kept`; a
    feedback PDF typst could not set, with its error, to `failed`)."""
    from ..output.folder import staged_dir, write_owned
    from ..render.data.check import check_csv, check_json
    from ..render.feedback import FEEDBACK_DIR, write_feedback
    from ..render.html.group import group_html
    from ..render.terminal.check import group_markdown

    written = []
    if feedback and any(rep.fname for rep in group.reports):
        with staged_dir(Path(out_dir) / FEEDBACK_DIR, owns=("check-*.md", "check-*.pdf"), writer="check", kept=kept) as tmp:
            write_feedback(tmp, group.reports, lang, pdf=pdf, failed=failed)
        written.append(f"{FEEDBACK_DIR}/")
    for name, data in (("check.csv", check_csv(group, lang, csv_locale)),
                       ("check.md", group_markdown(group, lang, rtol_pct, sheets).encode("utf-8")),
                       ("check.json", check_json(group, lang)),
                       (PAGE, group_html(check_page(out_dir, group, lang, rtol_pct, sheets)).encode("utf-8"))):
        written.append(write_owned(out_dir, name, data, writer="check", kept=kept).name)
    return written


def write_batch_page(out_dir: Path, rows: list[dict], lang: str, tolerance_pct: float | None = None) -> str:
    """group.html of a batch (with the verdicts of a check.json in the same folder)."""
    from ..output.folder import write_owned
    from ..render.html.group import group_html

    page = batch_page(out_dir, rows, lang, tolerance_pct, read_check_json(out_dir))
    return write_owned(out_dir, PAGE, group_html(page).encode("utf-8"), writer="batch").name



