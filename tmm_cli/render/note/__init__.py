"""The explanatory note (пояснительная записка): one document, three writers.

:func:`build_note` turns a ProjectResult into a :class:`~.model.Document` — front matter (title
page, task, abstract, contents, introduction), the chapters in the order of the course, the
assumptions, the conclusion, the list of sources and the appendix. The writers walk it:
:mod:`.typst` (note.typ, compiled here to note.pdf with the typst compiler and the fonts shipped in
``fonts/``), :mod:`.docx` (note.docx) and :mod:`.markdown` (report.md). Nothing is computed here:
every number is read from the result.
"""

from __future__ import annotations

import os
from pathlib import Path

from ...errors import TmmError
from ...limits import NOTE_TEMPLATE_BYTES
from .sources import source_text
from .typeset import FONT_FAMILIES, FONTS_DIR  # noqa: F401  (the note's fonts, shipped with tmm)


def textbook(lang: str) -> str:
    """The textbook's entry in the list of sources of `lang` (the assignment sheets cite it too)."""
    return source_text(lang)["book"]

STYLE_FILE = "note-style.typ"
NOTE_FILES = ("note.typ", STYLE_FILE, "note.pdf")
# the typst source of a DOCX-only run, kept only to ask typst for the contents' pages
PAGES_FILES = (".tmm-note.typ", ".tmm-note-style.typ")
DOCX_FILE = "note.docx"
# the note's own figures (drawn at the note's size, render/figures/note.py), in their order
NOTE_FIGURES = ("cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle",
                "gears_planetary", "gears_assembly", "gears_mesh")
# … and those of a mechanism file's chapters (sheets 1–2), drawn only when the result has a mechanism
# (tmm project --mechanism)
LINKAGE_NOTE_FIGURES = ("linkage_plans", "linkage_dynamics")
MAX_TEMPLATE_BYTES = NOTE_TEMPLATE_BYTES


def note_figures(result) -> tuple[str, ...]:
    """The note figures of this result, in their order: the mechanism's (if any; the construction of
    its synthesis first when the file records one), the cam's, the gears'."""
    linkage = getattr(result, "linkage", None)
    if linkage is None:
        return NOTE_FIGURES
    from ...linkage.synthesis_file import recorded_synthesis

    rec = recorded_synthesis(linkage.sheet1.mechanism)
    gas = ("linkage_indicator",) if getattr(linkage, "indicators", ()) else ()  # chapter 2: the gas loads
    return (("linkage_synthesis",) if rec is not None and rec.matches else ()) + LINKAGE_NOTE_FIGURES[:1] + gas \
        + LINKAGE_NOTE_FIGURES[1:] + NOTE_FIGURES


def note_figure_file(name: str, ext: str = "svg") -> str:
    return f"note_{name}.{ext}"


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


# --- the document -----------------------------------------------------------------------------------

# The chapters in the order of the course project. Sheets 1 and 2 (the linkage: structure and
# kinematics, force analysis and the flywheel) come first when a ProjectResult carries them —
# their builders go here, before the cam (issues 24, 25); each builder is (ctx) -> None and
# decides from the result whether it has anything to say.
def _chapters():
    from .cam_part import cam_chapter
    from .gears_part import gears_chapter

    return (
        _linkage_chapter,  # sheet 1 (issue 24)
        _dynamics_chapter,  # sheet 2 (issue 25)
        cam_chapter,
        gears_chapter,
    )


def _linkage_chapter(c) -> None:
    """Sheet 1's chapter; its modules (the linkage's) are imported only for a project with a mechanism."""
    if getattr(c.r, "linkage", None) is not None:
        from .linkage_part import linkage_chapter

        linkage_chapter(c)


def _dynamics_chapter(c) -> None:
    """Sheet 2's chapter, likewise."""
    if getattr(c.r, "linkage", None) is not None:
        from .dynamics_part import dynamics_chapter

        dynamics_chapter(c)


def build_note(result, lang: str, figures: dict | None = None, title=None):
    """The note as a Document. `figures` maps a figure name to (svg file, png file or None,
    width cm, height cm) of the note's own figures; a figure not given is left out with the
    words that refer to it."""
    from ...inputs.titleblock import TitleFields
    from .ctx import Ctx
    from .front import appendix_profile, assumptions, conclusion, front_matter, references
    from .glossary import GLOSSARY

    c = Ctx(result, lang, dict(figures or {}), glossary=GLOSSARY)
    front_matter(c, title or TitleFields())
    for chapter in _chapters():
        chapter(c)
    assumptions(c)
    conclusion(c)
    references(c)
    appendix_profile(c)
    c.doc.off = list(c.off)
    return c.doc


# --- typst ----------------------------------------------------------------------------------------


def compile_note(folder: Path, source: str = "note.typ", output: str = "note.pdf") -> Path:
    """Compile folder/source to folder/output (a folder holding only what tmm wrote: the staging
    folder) in a child process (render/note/typeset.py) with the fonts tmm ships; TmmError (one
    line) on any failure, a font it does not ship included (no silent fallback)."""
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


def prepare_note(folder: Path, result, lang: str, title, figures: dict, template: str | None = None,
                 pdf: bool = True, docx: bool = False):
    """Build the document and (for the PDF) write note.typ and note-style.typ; the figures need not
    be drawn yet. For the DOCX alone the same source goes to hidden files (:data:`PAGES_FILES`),
    which :func:`finish_note` lays out for the contents' pages and removes. Returns the document for
    :func:`finish_note`."""
    from ...inputs.titleblock import TitleFields
    from .front import title_meta
    from .typst import note_source

    folder = Path(folder)
    title = title or TitleFields()
    doc = build_note(result, lang, figures, title)
    try:
        if pdf or docx:
            from .ctx import Ctx

            meta = title_meta(Ctx(result, lang), title)
            source, style = ("note.typ", STYLE_FILE) if pdf else PAGES_FILES
            (folder / style).write_text(template if template is not None else default_template(), encoding="utf-8")
            (folder / source).write_text(note_source(doc, meta, style), encoding="utf-8")
    except BaseException:
        _remove_note(folder)
        raise
    return doc


def finish_note(folder: Path, doc, title, pdf: bool = True, docx: bool = False) -> list[str]:
    """Compile note.pdf and/or write note.docx (the figures are drawn by now); on any error the
    note's files are removed and the error raised. Returns the names of the figures used."""
    from ...inputs.titleblock import TitleFields

    folder = Path(folder)
    try:
        if pdf:
            compile_note(folder)
        if docx:
            from .docx import write_docx
            from .typeset import page_numbers

            # the contents' page numbers and the page count as typst lays the note out (when note.typ
            # is here: the PDF is written too), the DOCX's fields' results before any update
            source = next((n for n in ("note.typ", PAGES_FILES[0]) if (folder / n).is_file()), None)
            try:
                pages = page_numbers(folder, source) if source else None
            finally:
                for name in PAGES_FILES:
                    (folder / name).unlink(missing_ok=True)
            write_docx(doc, folder / DOCX_FILE, folder, title or TitleFields(), pages=pages)
    except BaseException:
        _remove_note(folder)
        raise
    return [b.name for b in doc.blocks if type(b).__name__ == "Figure"]


def _remove_note(folder: Path) -> None:
    for name in (*NOTE_FILES, DOCX_FILE, *PAGES_FILES):
        (folder / name).unlink(missing_ok=True)


def write_note(folder: Path, result, lang: str, title, figures: dict, template: str | None = None,
               docx: bool = False, pdf: bool = True) -> list[str]:
    """Write note.typ, note-style.typ and note.pdf (and note.docx) into `folder`; returns the names
    of the figures used.

    `figures` maps figure names to (svg, png or None, width cm, height cm), files already in
    `folder`; `template` is the style's text (default: the package's). On a typst error the
    note's files are removed and TmmError raised.
    """
    doc = prepare_note(folder, result, lang, title, figures, template, pdf=pdf, docx=docx)
    return finish_note(folder, doc, title, pdf=pdf, docx=docx)


def rewrite_docx(path: Path, lang: str, title=None) -> Path:
    """`tmm note --to docx`: note.docx for the project in `path` (a folder, or a file in it), written
    from its results.json (the run is repeated with the options it records, the note's figures drawn
    afresh). The text is the one tmm writes: edits of note.typ do not reach it."""
    import json
    import os
    import tempfile

    from ...project import run_project
    from ..figures.note import save_note_figure
    from ..figures.note_scales import figure_size_cm

    folder = Path(path)
    folder = folder if folder.is_dir() else folder.parent
    src = folder / "results.json"
    if not src.is_file():
        raise TmmError(f"no {src} here: the Word note is written from the project's results; run tmm project "
                       "--report docx in its folder's parent, or keep results.json beside the note")
    try:
        if src.stat().st_size > 16 << 20:
            raise ValueError
        data = json.loads(src.read_text(encoding="utf-8"))
        row, o = data["input"], data.get("options") or {}
        if not isinstance(row, dict) or not isinstance(o, dict):
            raise TypeError
    except (OSError, ValueError, KeyError, TypeError, RecursionError):
        raise TmmError(f"no {src} here: the Word note is written from the project's results; run tmm project "
                       "--report docx in its folder's parent, or keep results.json beside the note") from None
    v, kw = read_back(data, row, o, str(src))
    result = run_project(v, **kw)
    with tempfile.TemporaryDirectory(prefix=".tmm-note-", dir=folder) as tmp:
        tmp = Path(tmp)
        figures = {}
        for name in note_figures(result):
            save_note_figure(tmp, result, lang, name, raster=True)
            w, h = figure_size_cm(name, result.gears, result.linkage)
            figures[name] = (note_figure_file(name, "svg"), note_figure_file(name, "png"), w, h)
        write_note(tmp, result, lang, title, figures, docx=True, pdf=False)
        try:
            os.replace(tmp / DOCX_FILE, folder / DOCX_FILE)
        except OSError as exc:
            raise TmmError(f"cannot write the note for Word ({exc.strerror})") from None
    return folder / DOCX_FILE


def read_back(data: dict, row: dict, o: dict, src: str):
    """The variant and the options of a results.json read back (`tmm note --to docx`), held to the
    limits the command line holds them to (limits.py, the variants table's rules): a folder a
    teacher received is not trusted to ask for a 0.0001° step or a 10⁹ % tolerance. TmmError
    (one line naming the file and the key) otherwise."""
    from ... import limits
    from ...cam.design import CamChoice, check_choice
    from ...gears.design import parse_ratio
    from ...gears.shifted import parse_shift
    from ...variants import parse_row

    def cell(x) -> str:
        if x is None:
            return ""
        if isinstance(x, bool) or not isinstance(x, (int, float, str)) or len(str(x)) > 40:
            return "?"
        return str(x)

    scheme = row.get("scheme")
    csv_row = {k: cell(row.get(k)) for k in ("scheme", "l_bc_m", "nu_max_deg", "n_cam_rpm", "law", "phi_rise_deg",
                                              "phi_far_dwell_deg", "phi_return_deg")}
    csv_row["variant"] = cell(data.get("variant"))
    csv_row["gamma_max_deg" if scheme in (3, 4) else "s_max_m"] = cell(row.get("stroke"))
    v = parse_row(csv_row, src)

    def number(key, lo, hi, default=None):
        x = o.get(key, default)
        return None if x is None else limits.check_range(x if not isinstance(x, bool) else "?", lo, hi, f"{src}: {key}")

    kw = dict(crank_rpm=number("crank_rpm", *limits.CRANK_RPM), torque_nm=number("torque_nm", *limits.TORQUE_NM),
              step_deg=number("step_deg", *limits.STEP_DEG, default=10.0),
              tolerance_pct=number("tolerance_pct", *limits.TOLERANCE_PCT, default=5.0))
    planets = o.get("planets")
    kw["planets"] = None if planets is None else limits.check_int_range(planets, *limits.PLANETS, f"{src}: planets")
    ratio = o.get("ratio")
    if ratio is not None and (not isinstance(ratio, str) or len(ratio) > 20):
        raise TmmError(f"{src}: ratio is not a fraction such as 13/4; run tmm project again")
    kw["ratio"] = parse_ratio(ratio) if ratio else None
    shift = o.get("shift")
    if isinstance(shift, list) and len(shift) == 2 and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                                                           for x in shift):
        shift = parse_shift(f"{float(shift[0])!r},{float(shift[1])!r}")
    elif shift is not None:
        shift = parse_shift(shift if isinstance(shift, str) and len(shift) < 20 else "?")
    kw["shift"] = shift
    kw["a_w_mm"] = number("a_w_mm", 1.0, 1.0e5)
    select = o.get("select", "accurate")
    if select not in ("accurate", "smallest"):
        raise TmmError(f"{src}: select is not accurate or smallest; run tmm project again")
    kw["select"] = select
    choice = o.get("cam_choice")
    if choice:
        fields = ("r0_mm", "offset_mm", "l_oc_mm", "swing", "roller_mm")
        if not isinstance(choice, dict) or set(choice) - set(fields) \
                or any(not isinstance(choice.get(k), (int, float, type(None))) or isinstance(choice.get(k), bool)
                       for k in fields if k != "swing") or not isinstance(choice.get("swing"), (str, type(None))):
            raise TmmError(f"{src}: cam_choice is not a choice tmm writes; run tmm project again")
        choice = check_choice(v, CamChoice(**choice))
    kw["cam_choice"] = choice or None
    return v, kw


def markdown_note(result, lang: str, figure_files: list[str]) -> str:
    """The note as Markdown (report.md), with the screen PNGs (figure_files) as its pictures."""
    from ...i18n import tr
    from .markdown import markdown

    by_name = {Path(f).stem: f for f in figure_files}
    figures = {name: (by_name[name], None, 16.5, 10.0) for name in NOTE_FIGURES if name in by_name}
    doc = build_note(result, lang, figures)
    v = result.variant
    title = tr(lang, "TMM course project, variant {number}: explanatory note").format(number=v.number)
    return markdown(doc, title)
