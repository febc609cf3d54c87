"""The explanatory note (пояснительная записка): typst source, its PDF, and the Markdown report.

:func:`build_note` turns a ProjectResult into a :class:`~tmm_cli.render.note.doc.Doc` (section 1
the cam, section 2 the gears, the conclusion and the references, in the order of the textbook);
:func:`write_note` writes ``note.typ`` (the text, which a student may edit), ``note-style.typ``
(the style: this package's ``note-style.typ`` or the department's ``--note-template``) and compiles
``note.pdf`` with the typst compiler (imported here, lazily). :func:`markdown_note` writes the
same document as Markdown. Nothing is computed here: every number is read from the result.
"""

from __future__ import annotations

import os
from pathlib import Path

from ...errors import TmmError
from ...limits import NOTE_TEMPLATE_BYTES

STYLE_FILE = "note-style.typ"
NOTE_FILES = ("note.typ", STYLE_FILE, "note.pdf")
# the figures of the note, in its order (cam_profile_scaled is a drawing at scale, not a figure)
NOTE_FIGURES = ("cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle",
                "gears_planetary", "gears_assembly", "gears_mesh")
MAX_TEMPLATE_BYTES = NOTE_TEMPLATE_BYTES

TEXTBOOK = {
    "ru": "Пожбелко, В. И. Курсовое проектирование по теории механизмов и машин : учебное пособие. Ч. 2 / "
          "В. И. Пожбелко, П. Г. Веницкий, Н. И. Ахметшин ; под ред. В. И. Пожбелко. – Челябинск : "
          "Изд-во ЮУрГУ, 2003. – 52 с.",
    "en": "Pozhbelko, V. I., Venitsky, P. G., Akhmetshin, N. I. Course design in the theory of mechanisms and "
          "machines: a textbook. Part 2 / ed. by V. I. Pozhbelko. Chelyabinsk: South Ural State University, "
          "2003. 52 p. (in Russian)",
}


def default_template() -> str:
    """The package's style file (package data)."""
    return (Path(__file__).with_name(STYLE_FILE)).read_text(encoding="utf-8")


def read_template(path) -> str:
    """A department's style file; TmmError if it cannot be read as typst source."""
    from ...inputs.files import read_file

    p = Path(path)
    if not os.path.exists(p):
        raise TmmError(f"note template {p} does not exist; give a typst file (start from tmm's note-style.typ, see docs/note.md)")
    raw = read_file(p, f"note template {p}", MAX_TEMPLATE_BYTES)  # a regular file, its size checked first
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise TmmError(f"note template {p} is not UTF-8 text; save it as UTF-8") from None


def note_meta(result, lang: str, title) -> dict:
    """The title page's fields and words, as the style's `note` function reads them."""
    from ...i18n.lang import pick

    v = result.variant
    org = [s.strip() for s in (title.org or "").split(",") if s.strip()]
    return {
        "lang": lang,
        "doc-title": pick(lang, f"Explanatory note, TMM course project, variant {v.number}",
                          f"Пояснительная записка к курсовому проекту по ТММ, вариант {v.number}"),
        "org-lines": org,
        "title-lines": [pick(lang, "Explanatory note", "Пояснительная записка"),
                        pick(lang, "to the course project in the theory of mechanisms and machines",
                             "к курсовому проекту по теории механизмов и машин")],
        "topic": pick(lang, "«Synthesis of the cam and gear mechanisms»",
                      "«Синтез кулачкового и зубчатых механизмов»"),
        "variant-line": pick(lang, f"Variant {v.number}", f"Вариант {v.number}"),
        "designation": title.designation_for(0, v.number) + pick(lang, "", " ПЗ"),
        "teacher-label": pick(lang, "Supervisor", "Руководитель"),
        "teacher": title.teacher,
        "date-label": pick(lang, "date", "дата"),
        "student-label": pick(lang, "Student", "Автор работы"),
        "student": title.student,
        "group-label": pick(lang, "Group", "Группа"),
        "group": title.group,
        "city": getattr(title, "city", "") or "",
        "year": str(title.the_year),
        "contents-title": pick(lang, "Contents", "Содержание"),
        "figure-word": pick(lang, "Figure", "Рисунок"),
        "table-word": pick(lang, "Table", "Таблица"),
    }


MAX_FIGURE_HEIGHT_CM = 14.5
TEXT_WIDTH_CM = 16.5


def figure_width(path: Path) -> str | None:
    """The width to embed an SVG with, so that it is at most MAX_FIGURE_HEIGHT_CM tall."""
    import re

    try:
        head = Path(path).read_text(encoding="utf-8", errors="replace")[:2000]
    except OSError:
        return None
    m = re.search(r'<svg[^>]*\swidth="([\d.]+)(?:pt)?"[^>]*\sheight="([\d.]+)(?:pt)?"', head)
    if not m or float(m.group(2)) <= 0:
        return None
    width = min(TEXT_WIDTH_CM, MAX_FIGURE_HEIGHT_CM * float(m.group(1)) / float(m.group(2)))
    return f"{width:.1f}cm"


def build_note(result, lang: str, figures: dict[str, str], widths: dict[str, str] | None = None):
    """The note as a Doc: cam, gears, conclusion, references. `figures` maps names to files,
    `widths` names to the widths to embed them with (default: the text width)."""
    from .cam_part import cam_section
    from .ctx import Ctx
    from .gears_part import gears_section
    from .sentences import note_sentence

    c = Ctx(result, lang, {k: v for k, v in figures.items() if k in NOTE_FIGURES}, widths=dict(widths or {}))
    t = c.t
    doc = c.doc
    cam_section(c)
    gears_section(c)

    # conclusion
    cam, g = result.cam, result.gears
    z, p, v = cam.sizing, cam.profile, cam.variant
    doc.h(1, t("Conclusion", "Заключение"), numbered=False)
    size = (t(f"$l_(O C) = {c.q(z.l_oc_m * 1000, decimals=2)}$ mm", f"$l_(O C) = {c.q(z.l_oc_m * 1000, decimals=2)}$ мм")
            if v.is_rocker else t(f"offset $e = {c.q(z.e_m * 1000, decimals=2)}$ mm", f"эксцентриситет $e = {c.q(z.e_m * 1000, decimals=2)}$ мм"))
    doc.p(t(f"A cam mechanism of scheme {v.scheme} was designed for variant {v.number}: the base radius of the pitch "
            f"profile $r_0 = {c.q(z.r0_m * 1000, decimals=2)}$ mm, {size}, the roller radius "
            f"$r_\"р\" = {c.q(p.roller_m * 1000, decimals=2)}$ mm; the pressure angle does not exceed "
            f"{c.n(max(z.nu_rise_max_deg, z.nu_return_max_deg if z.closure == 'form' else 0), decimals=2)}° "
            f"(allowed {c.n(v.nu_max_deg)}°)" + (t("; the profile is not undercut.", "; подреза профиля нет.") if not p.undercut
                                                  else t("; the roller undercuts the profile (see the warnings).",
                                                         "; ролик подрезает профиль (см. предупреждения).")),
            f"Для варианта {v.number} спроектирован кулачковый механизм по схеме {v.scheme}: радиус теоретического "
            f"профиля $r_0 = {c.q(z.r0_m * 1000, decimals=2)}$ мм, {size}, радиус ролика "
            f"$r_\"р\" = {c.q(p.roller_m * 1000, decimals=2)}$ мм; угол давления не превышает "
            f"{c.n(max(z.nu_rise_max_deg, z.nu_return_max_deg if z.closure == 'form' else 0), decimals=2)}° "
            f"(допускается {c.n(v.nu_max_deg)}°)" + ("; подреза профиля нет." if not p.undercut
                                                      else "; ролик подрезает профиль (см. предупреждения).")))
    from .gears_part import _teeth

    sp = g.spur
    scheme_words = {"1": t("a single-row planetary reducer", "однорядный планетарный редуктор"),
                    "2": t("a double-row planetary reducer", "двухрядный планетарный редуктор"),
                    "1+1": t("two single-row planetary stages in series", "две последовательные однорядные планетарные ступени")}[g.scheme]
    doc.p(t(f"The drive: a motor of {g.motor_rpm} rpm, {scheme_words} with tooth numbers {_teeth(g.planetary)} and "
            f"{g.planetary.planets} planets ($i = {c.q(g.planetary.ratio, decimals=4)}$, deviation "
            f"{c.n(g.planetary.ratio_error_pct, decimals=2)} %), and the spur pair $z_1 = {sp.z1}$, $z_2 = {sp.z2}$, "
            f"$m = {c.q(sp.m_mm)}$ mm with the contact ratio $ε_α = {c.q(sp.eps_alpha, decimals=3)}$.",
            f"Привод: двигатель с частотой вращения {g.motor_rpm} об/мин, {scheme_words} с числами зубьев "
            f"{_teeth(g.planetary)} и {g.planetary.planets} сателлитами ($i = {c.q(g.planetary.ratio, decimals=4)}$, "
            f"отклонение {c.n(g.planetary.ratio_error_pct, decimals=2)} %) и простая передача $z_1 = {sp.z1}$, "
            f"$z_2 = {sp.z2}$, $m = {c.q(sp.m_mm)}$ мм с коэффициентом перекрытия $ε_α = {c.q(sp.eps_alpha, decimals=3)}$."))
    notes = []  # the cam's first, as in the note (ProjectResult.notes puts the gears' first)
    for n in tuple(cam.notes) + tuple(g.notes):
        if n not in notes:
            notes.append(n)
    assumptions = [note_sentence(n, lang) for n in notes if n.level == "assumption"]
    warnings = [note_sentence(n, lang) for n in notes if n.level == "warning"]
    if assumptions:
        doc.p(t("Assumptions made in the calculation:", "Допущения, принятые в расчёте:"))
        doc.items(assumptions)
    if warnings:
        doc.p(t("Warnings:", "Предупреждения:"))
        doc.items(warnings)
    else:
        doc.p(t("The calculation gave no warnings.", "Предупреждений расчёт не выдал."))

    # references
    doc.h(1, t("References", "Список литературы"), numbered=False)
    doc.raw("#set par(first-line-indent: 0pt)\n#enum(numbering: \"1.\", indent: 0pt, [" + _typst_markup(TEXTBOOK[lang]) + "])",
            "1. " + TEXTBOOK[lang])
    return doc, c.used_figures


def _typst_markup(text: str) -> str:
    from .doc import typst_escape

    return typst_escape(text, start=False)


def note_source(doc, meta: dict) -> str:
    """The text of note.typ: import of the style, the title page fields, the body."""
    from .doc import typst_string

    def value(x):
        if isinstance(x, list):
            return "(" + "".join(typst_string(s) + ", " for s in x) + ")"
        return typst_string(str(x))

    fields = ",\n".join(f"  {k}: {value(v)}" for k, v in meta.items())
    head = (f"// The explanatory note written by tmm. Edit the text freely and recompile in this folder:\n"
            f"//   tmm note        (or the standalone typst: typst compile note.typ)\n"
            f"// The style (page, fonts, title page) is in {STYLE_FILE}.\n"
            f"#import \"{STYLE_FILE}\": *\n"
            f"#let meta = (\n{fields},\n)\n"
            f"#show: note.with(meta)\n")
    return doc.to_typst(head)


def compile_note(folder: Path, source: str = "note.typ", output: str = "note.pdf") -> Path:
    """Compile folder/source to folder/output (a folder holding only what tmm wrote: the staging
    folder) in a child process (render/note/typeset.py); TmmError (one line) on any failure."""
    from .typeset import typeset

    return typeset(Path(folder), source, output)


def recompile(path: Path) -> Path:
    """`tmm note`: compile an edited note.typ (a folder holding it, or the .typ file) to PDF beside it.

    typst's root is a private copy of the folder's regular files (no link is followed, nothing
    outside the folder is read), and the PDF replaces the old one only once it is complete.
    """
    from .typeset import typeset_in_copy

    path = Path(path)
    src = path / "note.typ" if path.is_dir() else path
    if not src.is_file():
        raise TmmError(f"no {src} here; run tmm note in the folder of the note (or give the .typ file)")
    if src.suffix != ".typ":
        raise TmmError(f"{src} is not a typst file (.typ)")
    return typeset_in_copy(src.parent, src.name, src.with_suffix(".pdf"))


def write_note(folder: Path, result, lang: str, title, figures: dict[str, str], template: str | None = None) -> list[str]:
    """Write note.typ, note-style.typ and note.pdf into `folder`; returns the figure names used.

    `figures` maps figure names to files already in `folder`; `template` is the style's text
    (default: the package's). On a typst error the three files are removed and TmmError raised.
    """
    from ...inputs.titleblock import TitleFields

    folder = Path(folder)
    widths = {name: w for name, file in figures.items() if (w := figure_width(folder / file))}
    doc, used = build_note(result, lang, figures, widths)
    meta = note_meta(result, lang, title or TitleFields())
    try:
        (folder / STYLE_FILE).write_text(template if template is not None else default_template(), encoding="utf-8")
        (folder / "note.typ").write_text(note_source(doc, meta), encoding="utf-8")
        compile_note(folder)
    except BaseException:
        for name in NOTE_FILES:
            (folder / name).unlink(missing_ok=True)
        raise
    return used


def markdown_note(result, lang: str, figure_files: list[str]) -> str:
    """The note as Markdown (headings, tables, figures with captions) for report.md."""
    from ...i18n.lang import pick

    by_name = {Path(f).stem: f for f in figure_files}
    doc, _ = build_note(result, lang, by_name)
    v = result.variant
    title = pick(lang, f"TMM course project, variant {v.number}: explanatory note",
                 f"Курсовой проект по ТММ, вариант {v.number}: пояснительная записка")
    return doc.to_markdown(title)
