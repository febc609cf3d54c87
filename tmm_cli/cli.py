"""The `tmm` command line: parse, call the core, hand the result to the renderers.

Heavy modules (numpy, scipy, matplotlib, the core) are imported inside the commands, so
``tmm --help`` stays instant. Every bad input becomes one line on stderr and exit status 2.
"""

from __future__ import annotations

if __name__ == "__main__":  # `python -m tmm_cli.cli`: run the importable module, so that the
    from tmm_cli.cli import main  # command modules (which import it) see one cli, not two

    main()

import os
import sys
from pathlib import Path

import click

from .errors import TmmError

CONTEXT = {"help_option_names": ["-h", "--help"], "max_content_width": 100}


class TmmGroup(click.Group):
    """A click group whose errors are one line on stderr with exit status 2, never a traceback."""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        """Run the command line; help, click's messages and our errors follow --lang / the locale."""
        lang = _requested_lang(list(sys.argv[1:] if args is None else args))  # args stay as given (click
        # expands wildcards itself on Windows when they are None)
        if lang == "ru":
            from .render.help_ru import russian

            with russian(self):
                return self._main(args, prog_name, complete_var, standalone_mode, lang, **extra)
        return self._main(args, prog_name, complete_var, standalone_mode, lang, **extra)

    def _main(self, args, prog_name, complete_var, standalone_mode, lang, **extra):
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, standalone_mode, **extra)
        import warnings

        from .interrupt import Stopped, handle_signals

        say = _words(lang)
        try:
            with handle_signals(), warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)  # numpy's overflow chatter is never shown
                rv = super().main(args, prog_name or "tmm", complete_var, False, **extra)
        except TmmError as exc:
            _fail(str(exc), lang)
        except click.exceptions.Abort:
            click.echo(f"tmm: {say('aborted')}", err=True)
            sys.exit(1)
        except click.ClickException as exc:
            _fail(exc.format_message(), lang)
        except Stopped as exc:  # Ctrl-C (130) or SIGTERM (143) during a command, see interrupt.py
            _remove_what_a_stop_left()
            click.echo(f"tmm: {say(exc.message)}", err=True)
            sys.exit(exc.exit_code)
        except KeyboardInterrupt as exc:  # Ctrl-C (130) or SIGTERM (143), see interrupt.py
            _remove_what_a_stop_left()
            click.echo(f"tmm: {say(getattr(exc, 'message', '') or 'interrupted')}", err=True)
            sys.exit(getattr(exc, "exit_code", 130))
        except Exception as exc:  # a bug: one line, not a traceback, unless TMM_DEBUG is set
            if os.environ.get("TMM_DEBUG"):
                raise
            click.echo(f"tmm: {say('internal error')}: {exc.__class__.__name__}: {exc} "
                       f"({say('run with TMM_DEBUG=1 for details')})", err=True)
            sys.exit(1)
        sys.exit(rv if isinstance(rv, int) else 0)

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt as exc:  # past click's Abort ("Aborted!", exit 1): exit 130 / 143
            from .interrupt import Stopped

            raise Stopped(exc) from None
        except Exception:
            from .interrupt import Stopped, received

            stop = received()
            if stop is None:
                raise
            raise Stopped(stop) from None  # the error a signal caused: an interruption (see received)


def _remove_what_a_stop_left() -> None:
    """After Ctrl-C/SIGTERM: the staging folders and temporary files this process still has
    registered (a signal between creating one and entering the block that removes it)."""
    files = sys.modules.get("tmm_cli.render.files")  # nothing was staged if it was never imported
    if files is not None:
        files.remove_active_staging()


def _requested_lang(args: list[str]) -> str:
    """The language of this run: --lang on the command line (the last one wins), else the locale."""
    lang = None
    for i, a in enumerate(args):
        if a == "--":
            break
        if a == "--lang" and i + 1 < len(args):
            lang = args[i + 1]
        elif a.startswith("--lang="):
            lang = a.split("=", 1)[1]
    if lang in ("ru", "en"):
        return lang
    from .render.i18n import default_lang

    return default_lang()


def _words(lang: str):
    if lang != "ru":
        return lambda w: w
    from .render.help_ru import WORDS

    return lambda w: WORDS.get(w, w)


def _fail(message: str, lang: str = "en") -> None:
    line = " ".join(str(message).split())
    if lang == "ru":
        from .render.help_ru import translate_error

        line = translate_error(line)
    click.echo(f"tmm: {_words(lang)('error')}: {line}", err=True)
    sys.exit(2)


def _lang(lang: str | None) -> str:
    """--lang of the command, else --lang given before it (`tmm --lang ru cam …`), else the locale."""
    if lang:
        return lang
    ctx = click.get_current_context(silent=True)
    if ctx is not None and ctx.find_root().params.get("lang"):
        return ctx.find_root().params["lang"]
    from .render.i18n import default_lang

    return default_lang()


def _console(lang: str):
    """A rich console; 120 columns when the output is a file or a pipe (rich would assume 80)."""
    from rich.console import Console

    console = Console(highlight=False)
    if not console.is_terminal:
        console = Console(highlight=False, width=120)
    return console


def _variant(number: str, variants_file: str | None):
    from .variants import get_variant

    return get_variant(number, variants_file)


def _out_folder(out: str | None, number: int) -> Path:
    base = Path(out) if out else Path("tmm-out")
    return base / f"variant-{number:02d}"


def _print_json(obj) -> None:
    from .render.files import json_text

    click.echo(json_text(obj))  # strict JSON: never a bare NaN or Infinity


def _print_notes(console, notes, lang: str) -> None:
    from .render.report import print_notes

    print_notes(console, notes, lang)


def _print_files(console, folder: Path, names: list[str], lang: str) -> None:
    from .render.i18n import pick

    if names:
        console.print(pick(lang, "Files written to ", "Файлы записаны в ") + f"[bold]{folder}[/]: " + ", ".join(names))


def _emit(folder: Path, files: dict, figures, fmt: str, json_doc, show, notes, lang: str, owns=(), extra=None,
          figure_names=()) -> None:
    """Write `files` (name -> JSON object or text) and the figures atomically, then either print
    `json_doc` alone or the tables (`show(console)`), the notes and the list of files.

    `figures(names=None)` draws the figures (a dict name -> Figure); given their `figure_names`,
    they are drawn and saved one by one over two processes where a fork is possible, as
    `tmm project` does."""
    from .render.files import save_figures, staged_dir, staged_names, write_json, write_text

    with staged_dir(folder, owns) as tmp:
        for name, content in files.items():
            (write_text if isinstance(content, str) else write_json)(tmp / name, content)
        if figures is not None:
            _save_figures(tmp, figures, figure_names, fmt)
        if extra is not None:  # e.g. the A1 drawing sheet (--sheets)
            extra(tmp)
        written = staged_names(tmp)
    if json_doc is not None:
        _print_json(json_doc)
        return
    console = _console(lang)
    show(console)
    _print_notes(console, notes, lang)
    _print_files(console, folder, written, lang)


def _figure_names(sheet: str) -> tuple:
    from .render.report import CAM_FIGURES, GEAR_FIGURES

    return CAM_FIGURES if sheet == "cam" else GEAR_FIGURES


def _save_figures(tmp: Path, figures, names, fmt: str) -> None:
    from .render.figure_kit import SharedWork, can_fork
    from .render.files import save_figures

    if len(names) < 2 or not can_fork():
        save_figures(tmp, figures(), fmt)
        return
    from .render.report import _largest_first, prepare_figures

    prepare_figures(set())
    tasks = [lambda n=n: save_figures(tmp, figures([n]), fmt) for n in _largest_first(names, set())]
    with SharedWork(tasks) as work:
        work.wait_shared()


# Shared options -----------------------------------------------------------------------------

variant_option = click.option("--variant", "-v", "variant", required=True, metavar="N", help="Variant number from Table 1.2 (1–68).")
variants_file_option = click.option(
    "--variants-file", type=click.Path(dir_okay=False), default=None, metavar="PATH",
    help="Use your own table in the format of variants/table_1_2.csv.",
)
out_option = click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Output folder (default ./tmm-out); files go to DIR/variant-NN/.")
format_option = click.option("--format", "fmt", type=click.Choice(["png", "svg", "pdf"]), default="png", show_default=True, help="Figure file format.")
no_plots_option = click.option("--no-plots", is_flag=True, help="Do not draw figures (faster).")
sheets_option = click.option("--sheets", is_flag=True, help="Also write the A1 drawing sheet (DXF and PDF, ESKD frame and title block).")
json_option = click.option("--json", "as_json", is_flag=True, help="Print only JSON on stdout.")
lang_option = click.option("--lang", type=click.Choice(["ru", "en"]), default=None, help="Output language (default: from the locale).")
step_option = click.option("--step", "step_deg", type=float, default=10.0, show_default=True, metavar="DEG", help="Cam angle step of the printed tables [deg].")
crank_option = click.option("--crank-rpm", type=float, default=None, metavar="R", help="Crank speed of the linkage n_кр [rpm] (default: the book's 220 rpm, stated in the output).")
torque_option = click.option("--torque", "torque_nm", type=float, default=None, metavar="NM", help="Mean reduced moment M from sheet 2 [N·m], for the motor power (§2.6).")
ratio_option = click.option("--ratio", default=None, metavar="P/Q", help="Force the planetary ratio fraction of the book's procedure, e.g. 13/4.")
tolerance_option = click.option("--tolerance", "tolerance_pct", type=float, default=5.0, show_default=True, metavar="PCT", help="Allowed planetary ratio error [%].")
planets_option = click.option("--planets", type=int, default=None, metavar="K", help="Force the number of planets.")
shift_option = click.option("--shift", "shift", default=None, metavar="X1,X2|auto", help="Profile shifts of the spur pair (beyond the book), e.g. 0.3,-0.3; auto: no undercut, then a balanced split.")
aw_option = click.option("--aw", "a_w_mm", type=float, default=None, metavar="MM", help="Required centre distance of the spur pair a_w [mm]: x1 + x2 from it, split as auto.")


def _parse_shift(shift: str | None):
    if shift is None:
        return None
    from .gears.shifted import parse_shift

    return parse_shift(shift)


select_option = click.option("--select", "select", type=click.Choice(["accurate", "smallest"]), default="accurate", show_default=True,
                             help="Which reducer to carry: the most accurate ratio among sets at most one tooth larger than the smallest, or the smallest.")


def cam_choice_options(f):
    """The student's say over the cam (issue 8): --r0, --offset, --l-oc, --swing, --roller."""
    for args, kw in reversed((
        (("--r0", "cam_r0"), dict(type=float, metavar="MM", help="Your base radius r0 of the pitch curve [mm] (checked, not replaced).")),
        (("--offset", "cam_offset"), dict(type=float, metavar="MM", help="Your offset e of a translating follower [mm] (e > 0: axis right of the cam centre).")),
        (("--l-oc", "cam_l_oc"), dict(type=float, metavar="MM", help="Your distance l_OC from the cam centre to the rocker pivot [mm].")),
        (("--swing", "cam_swing"), dict(type=click.Choice(["same", "opposite"]), help="Rocker turns on the rise the same way as the cam or opposite.")),
        (("--roller", "cam_roller"), dict(type=float, metavar="MM", help="Your roller radius [mm] (default: 0.2·r0, at most 0.8·ρ_min).")),
    )):
        f = click.option(*args, default=None, **kw)(f)
    return f


def _cam_choice(kw: dict):
    from .cam.design import CamChoice

    c = CamChoice(kw.pop("cam_r0", None), kw.pop("cam_offset", None), kw.pop("cam_l_oc", None),
                  kw.pop("cam_swing", None), kw.pop("cam_roller", None))
    return c if c.given else None


stiffness_option = click.option("--stiffness", is_flag=True, help="Also compute the spur pair's mesh stiffness (beyond the course, informative; V. P. Tarasik's method).")


def title_options(f):
    """--student, --group, --teacher, --org, --designation: the title block and the note's title page."""
    helps = {
        "student": ("TEXT", "Student's name for the title block and the note, e.g. \"Иванов И. И.\" (or in tmm.toml)."),
        "group": ("TEXT", "Student's group (or in tmm.toml)."),
        "teacher": ("TEXT", "Teacher's name (or in tmm.toml)."),
        "org": ("TEXT", "University and department (or in tmm.toml)."),
        "designation": ("TEXT", "Drawing designation (default: built from the sheet and variant numbers)."),
    }
    for name, (metavar, text) in reversed(helps.items()):
        f = click.option(f"--{name}", f"title_{name}", default=None, metavar=metavar, help=text)(f)
    return f


def _title(kwargs: dict):
    """Pop the title_* options out of a command's kwargs and merge them with tmm.toml."""
    from .titleblock import title_fields

    given = {k[len("title_"):]: kwargs.pop(k) for k in list(kwargs) if k.startswith("title_")}
    return title_fields(given)


def _parse_ratio(ratio: str | None):
    if ratio is None:
        return None
    from .gears.design import parse_ratio

    return parse_ratio(ratio)


@click.group(cls=TmmGroup, context_settings=CONTEXT)
@click.version_option(package_name="tmm", prog_name="tmm")
@lang_option
def cli(lang):
    """tmm — the calculation part of the TMM course project (Pozhbelko et al., 2003, part 2).

    Sheet 3: cam mechanism synthesis (`tmm cam`). Sheet 4: gear drive synthesis (`tmm gears`).
    Both at once, with a report: `tmm project --variant 17`. Teachers: `tmm batch`, `tmm check`.
    """


# tmm variants ------------------------------------------------------------------------------


@cli.group("variants", invoke_without_command=True, context_settings=CONTEXT)
@variants_file_option
@lang_option
@click.pass_context
def variants_cmd(ctx, variants_file, lang):
    """List Table 1.2 (the 68 variants of sheet 3); `tmm variants show N` explains one row."""
    ctx.obj = {"variants_file": variants_file, "lang": lang}
    if ctx.invoked_subcommand is None:
        from .render.variants_tables import print_variant_table
        from .variants import load_table

        lang = _lang(lang)
        print_variant_table(_console(lang), load_table(variants_file), lang)


@variants_cmd.command("show", context_settings=CONTEXT)
@click.argument("number")
@variants_file_option
@lang_option
@click.pass_context
def variants_show(ctx, number, variants_file, lang):
    """Show one variant with the meaning of each field."""
    from .render.variants_tables import print_variant_detail

    variants_file = variants_file or ctx.obj.get("variants_file")
    lang = _lang(lang or ctx.obj.get("lang"))
    print_variant_detail(_console(lang), _variant(number, variants_file), lang)


# tmm cam -----------------------------------------------------------------------------------


@cli.command("cam", context_settings=CONTEXT)
@variant_option
@variants_file_option
@out_option
@format_option
@no_plots_option
@json_option
@step_option
@cam_choice_options
@sheets_option
@title_options
@lang_option
def cam_cmd(variant, variants_file, out, fmt, no_plots, as_json, step_deg, sheets, lang, **title_kw):
    """Sheet 3: follower diagrams, main dimensions, cam profile, pressure angle."""
    choice = _cam_choice(title_kw)
    title = _title(title_kw)
    from .cam.design import design_cam
    from .render.cam_json import profile_csv
    from .render.files import ensure_writable_dir
    from .render.report import cam_document

    lang = _lang(lang)
    v = _variant(variant, variants_file)
    folder = _out_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = design_cam(v, step_deg=step_deg, choice=choice)
    doc = cam_document(v, result, lang)

    def figures(names=None):
        from .render.cam_figures import cam_figures

        return cam_figures(result, lang, names=names)

    def show(console):
        from .render.cam_tables import print_cam

        print_cam(console, result, lang)

    def sheet(tmp):
        from .render.sheets import save_sheet, sheet3

        save_sheet(sheet3(result, lang, title), tmp, "sheet3")

    _emit(folder, {"cam.json": doc, "cam_profile.csv": profile_csv(result)}, None if no_plots else figures,
          fmt, doc if as_json else None, show, result.notes, lang, owns=("cam_*.*", "sheet3.*"),
          extra=sheet if sheets else None, figure_names=_figure_names("cam"))


# tmm gears ---------------------------------------------------------------------------------


@cli.command("gears", context_settings=CONTEXT)
@variant_option
@variants_file_option
@crank_option
@torque_option
@ratio_option
@tolerance_option
@planets_option
@shift_option
@aw_option
@select_option
@stiffness_option
@out_option
@format_option
@no_plots_option
@json_option
@sheets_option
@title_options
@lang_option
def gears_cmd(variant, variants_file, crank_rpm, torque_nm, ratio, tolerance_pct, planets, stiffness, shift, a_w_mm, select, out, fmt, no_plots, as_json, sheets, lang, **title_kw):
    """Sheet 4: motor, ratio split, planetary reducer synthesis, spur pair to the cam."""
    title = _title(title_kw)
    from .gears.design import design_gears
    from .render.files import ensure_writable_dir
    from .render.report import gears_document

    lang = _lang(lang)
    v = _variant(variant, variants_file)
    folder = _out_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = design_gears(
        v.n_cam_rpm, crank_rpm=crank_rpm, torque_nm=torque_nm, ratio=_parse_ratio(ratio),
        tolerance_pct=tolerance_pct, planets=planets, stiffness=stiffness, shift=_parse_shift(shift), a_w_mm=a_w_mm, select=select,
    )
    doc = gears_document(v, result, lang)

    def figures(names=None):
        from .render.gears_figures import gears_figures

        return gears_figures(result, lang, names=names)

    def show(console):
        from .render.gears_tables import print_gears

        print_gears(console, result, lang)

    def sheet(tmp):
        from .render.sheets import save_sheet, sheet4

        save_sheet(sheet4(result, v.number, lang, title), tmp, "sheet4")

    _emit(folder, {"gears.json": doc}, None if no_plots else figures, fmt, doc if as_json else None, show,
          result.notes, lang, owns=("gears_*.*", "sheet4.*"), extra=sheet if sheets else None,
          figure_names=_figure_names("gears"))


# tmm project -------------------------------------------------------------------------------


@cli.command("project", context_settings=CONTEXT)
@variant_option
@variants_file_option
@crank_option
@torque_option
@ratio_option
@tolerance_option
@planets_option
@shift_option
@aw_option
@select_option
@stiffness_option
@out_option
@format_option
@no_plots_option
@json_option
@click.option("--report", "report", type=click.Choice(["md", "pdf"]), default="pdf", show_default=True,
              help="pdf: the explanatory note (note.pdf and its source note.typ); md: report.md.")
@click.option("--note-template", "note_template", type=click.Path(dir_okay=False), default=None, metavar="FILE",
              help="A typst style file replacing the note's (see docs/note.md).")
@step_option
@click.option("--no-sheets", is_flag=True, help="Do not write the A1 drawing sheets sheet3/sheet4 (.dxf, .pdf).")
@cam_choice_options
@title_options
@lang_option
def project_cmd(variant, variants_file, crank_rpm, torque_nm, ratio, tolerance_pct, planets, stiffness, shift, a_w_mm, select, out, fmt, no_plots, as_json, report, note_template, step_deg, no_sheets, lang, **title_kw):
    """The whole project for one variant: sheet 4 then sheet 3, figures, results.json, the note and the drawing sheets."""
    choice = _cam_choice(title_kw)
    title = _title(title_kw)
    template = None
    if note_template is not None:
        from .render.note import read_template

        template = read_template(note_template)
    from .project import run_project
    from .render.files import ensure_writable_dir
    from .render.report import write_project_folder

    lang = _lang(lang)
    v = _variant(variant, variants_file)
    folder = _out_folder(out, v.number)
    ensure_writable_dir(folder.parent)
    result = run_project(
        v, crank_rpm=crank_rpm, torque_nm=torque_nm, step_deg=step_deg,
        ratio=_parse_ratio(ratio), tolerance_pct=tolerance_pct, planets=planets, stiffness=stiffness,
        shift=_parse_shift(shift), a_w_mm=a_w_mm, select=select, cam_choice=choice,
    )
    console = None if as_json else _console(lang)
    shown: list[str] = []

    def render_report() -> None:
        """The terminal report, rendered into a string while the figures are drawn (≈ 0.3 s),
        printed once the folder is in place (nothing is printed for a run that fails)."""
        from .render.report import print_project

        if console.legacy_windows:  # the old Windows console takes no ANSI text: printed afterwards
            return
        with console.capture() as capture:
            print_project(console, result, lang)
        shown.append(capture.get())

    doc, written = write_project_folder(result, folder, lang, fmt=fmt, plots=not no_plots, report=report, title=title,
                                        note_template=template, sheets=not no_sheets,
                                        meanwhile=None if as_json else render_report)
    if as_json:  # the very text of results.json (encoding 180 kB of JSON twice costs ~0.1 s)
        click.echo((folder / "results.json").read_text(encoding="utf-8"), nl=False)
        return
    if shown:
        console.file.write(shown[0])
        console.file.flush()
    else:
        from .render.report import print_project

        print_project(console, result, lang)
    _print_files(console, folder, written, lang)


# tmm batch ---------------------------------------------------------------------------------


@cli.command("batch", context_settings=CONTEXT)
@click.option("--variants", "variants_spec", default=None, metavar="LIST", help="Variants, e.g. 1-68 or 3,17,40.")
@click.option("--roster", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="CSV with columns student,variant[,crank_rpm][,torque].")
@variants_file_option
@crank_option
@torque_option
@out_option
@format_option
@click.option("--jobs", "-j", type=int, default=None, metavar="N", help="Parallel worker processes (default: number of cores).")
@no_plots_option
@click.option("--report", "report", type=click.Choice(["md", "pdf", "none"]), default="md", show_default=True, help="Per-variant report format.")
@click.option("--csv-locale", type=click.Choice(["ru", "en"]), default=None, help="summary.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).")
@sheets_option
@lang_option
def batch_cmd(variants_spec, roster, variants_file, crank_rpm, torque_nm, out, fmt, jobs, no_plots, report, csv_locale, sheets, lang):
    """Teachers: run many variants or a class roster in parallel and write summary.csv."""
    from .batch import jobs_from_roster, jobs_from_spec, run_batch
    from .render.batch_render import print_batch, print_batch_intro
    from .render.files import ensure_writable_dir

    lang = _lang(lang)
    if (variants_spec is None) == (roster is None):
        raise TmmError("give exactly one of --variants (e.g. 1-68) or --roster FILE")
    out_dir = ensure_writable_dir(Path(out) if out else Path("tmm-out"))
    console = _console(lang)
    if variants_spec is not None:  # the whole list is checked against the table before any work
        rows, bad = jobs_from_spec(variants_spec, crank_rpm, torque_nm, variants_file), []
        print_batch_intro(console, lang, default_crank=crank_rpm is None)
    else:
        plan = jobs_from_roster(roster, crank_rpm, torque_nm, variants_file)
        rows, bad = plan.jobs, plan.bad
        print_batch_intro(console, lang, roster=plan)
    summary = run_batch(
        rows, bad, out_dir, variants_file=variants_file, lang=lang, fmt=fmt,
        plots=not no_plots, report=None if report == "none" else report, jobs_n=jobs, progress=True,
        csv_locale=csv_locale, sheets=sheets,
    )
    print_batch(console, summary, out_dir, lang)
    return 1 if summary.failed else 0


# tmm check ---------------------------------------------------------------------------------


@cli.command("check", context_settings=CONTEXT)
@click.option("--variant", "-v", "variant", default=None, metavar="N", help="Variant number (one student).")
@click.option("--answers", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="The student's numbers (TOML or CSV, keys in `tmm check --keys`).")
@click.option("--roster", type=click.Path(dir_okay=False), default=None, metavar="FILE", help="Class roster CSV (student,variant[,crank_rpm][,torque]).")
@click.option("--answers-dir", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Folder with one answers file per student (STUDENT.toml or STUDENT.csv).")
@variants_file_option
@crank_option
@torque_option
@click.option("--rtol", "rtol_pct", type=float, default=3.0, show_default=True, metavar="PCT", help="Tolerance for graphical quantities [%].")
@click.option("--keys", "show_keys", is_flag=True, help="List the answer keys and exit.")
@click.option("--sheet", "sheet", type=click.Choice(["3", "4", "all"]), default="all", show_default=True, help="Which sheet's required keys a student must give.")
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR", help="Group check: folder for check.csv and check.md (default ./tmm-out).")
@click.option("--csv-locale", type=click.Choice(["ru", "en"]), default=None, help="check.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).")
@json_option
@lang_option
def check_cmd(variant, answers, roster, answers_dir, variants_file, crank_rpm, torque_nm, rtol_pct, show_keys, sheet, out, csv_locale, as_json, lang):
    """Teachers: check a student's numbers against the computed ones."""
    from .check import SHEETS, check_group, check_one, read_answers
    from .render.check_render import print_check, print_group, print_keys

    lang = _lang(lang)
    console = _console(lang)
    if show_keys:
        print_keys(console, lang)
        return 0
    sheets = SHEETS if sheet == "all" else (sheet,)
    if roster is not None or answers_dir is not None:
        if roster is None or answers_dir is None:
            raise TmmError("group check needs both --roster FILE and --answers-dir DIR")
        from .render.check_render import group_csv, group_markdown
        from .render.files import ensure_writable_dir, read_manifest, refuse_foreign, write_owned

        out_dir = ensure_writable_dir(Path(out) if out else Path("tmm-out"))
        if out_dir.is_dir():  # a check.csv of the teacher's own is refused before any work
            refuse_foreign(out_dir, ["check.csv", "check.md"], read_manifest(out_dir)["files"])
        group = check_group(roster, answers_dir, variants_file=variants_file, crank_rpm=crank_rpm, torque_nm=torque_nm,
                            rtol_pct=rtol_pct, sheets=sheets)
        write_owned(out_dir, "check.csv", group_csv(group, lang, csv_locale or lang))
        write_owned(out_dir, "check.md", group_markdown(group, lang, rtol_pct, sheets).encode("utf-8"))
        if as_json:
            _print_json(group.to_json())
        else:
            from rich.markup import escape

            from .render.i18n import pick

            console.print("[cyan]ℹ[/] " + escape(pick(lang, f"Roster {roster}: read as {group.roster_encoding}.",
                                                         f"Список {roster}: кодировка {group.roster_encoding}.")))
            print_group(console, group, lang)
            _print_files(console, out_dir, ["check.csv", "check.md"], lang)
        return 0 if group.all_passed else 1
    if variant is None or answers is None:
        raise TmmError("give --variant N and --answers FILE (or --roster FILE with --answers-dir DIR)")
    v = _variant(variant, variants_file)
    report = check_one(v, read_answers(answers), crank_rpm=crank_rpm, torque_nm=torque_nm, rtol_pct=rtol_pct, sheets=sheets)
    if as_json:
        _print_json(report.to_json())
    else:
        print_check(console, report, lang)
    return 0 if report.passed else 1


# Commands kept in their own modules (each imports only click at start-up) -----------------------

from .commands.linkage import linkage_cmd  # noqa: E402  (needs the names defined above)
from .commands.planetary import planetary_cmd  # noqa: E402

cli.add_command(linkage_cmd)
cli.add_command(planetary_cmd)

from .commands.note import note_cmd  # noqa: E402  (issue 11: recompile an edited note)

cli.add_command(note_cmd)

# Limits on every number a user gives (docs/limits.md): ranges set on the options by name
from .limits import apply_option_limits  # noqa: E402

apply_option_limits(cli)

main = cli

if __name__ == "__main__":  # pragma: no cover
    cli()
