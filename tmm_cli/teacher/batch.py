"""Teachers' batch: many variants or a class roster, run in parallel, one summary row each.

A failing row never stops the batch: it becomes a row with its reason. The summary row is read
from the same JSON document that ``results.json`` holds, so the summary can never disagree with
the per-variant folders. The output folder's manifest records the folders of the last batch run:
a new run first removes them (only the files `tmm` wrote), so ``summary.csv`` always describes
exactly the folders beside it, and two rosters or runs are never mixed. Ctrl-C or SIGTERM stop the
workers at once; the summary then lists what finished and marks the rest "not run".
"""

from __future__ import annotations

import os
import re
from dataclasses import field
from pathlib import Path

from .. import limits
from ..errors import TmmError
from ..inputs.names import collision_key, display_name, file_name
from ..records import record
from ..i18n.lang import pick

# key, English header, Russian header, numeric
SUMMARY_FIELDS = (
    ("student", "student", "студент", False),
    ("group", "group", "группа", False),
    ("variant", "variant", "вариант", True),
    ("scheme", "scheme", "схема", True),
    ("law", "law", "закон", True),
    ("status", "status", "статус", False),
    ("crank_rpm", "crank_rpm", "n_кр, об/мин", True),
    ("n_motor_rpm", "n_motor_rpm", "n_д, об/мин", True),
    ("power_kw", "power_kw", "N_д, кВт", True),
    ("i_spur", "i_spur", "i_пп (простая передача)", True),
    ("i_planetary", "i_planetary", "i_пл", True),
    ("planetary_scheme", "planetary_scheme", "схема редуктора", False),
    ("teeth", "teeth", "зубья z_k/z_c/z_n", False),
    ("planets", "planets", "сателлиты k", False),
    ("ratio_error_pct", "ratio_error_pct", "погрешность i_пл, %", True),
    ("z1", "z1", "z1", True),
    ("z2", "z2", "z2", True),
    ("eps_alpha", "eps_alpha", "ε_α", True),
    ("r0_mm", "r0_mm", "r0, мм", True),
    ("e_mm", "e_mm", "e, мм", True),
    ("l_oc_mm", "l_oc_mm", "l_OC, мм", True),
    ("roller_mm", "roller_mm", "r_р, мм", True),
    ("nu_rise_deg", "nu_rise_deg", "ν_у, °", True),
    ("nu_return_deg", "nu_return_deg", "ν_в, °", True),
    ("undercut", "undercut", "подрезание", True),
    ("pressure_angle", "pressure_angle", "угол давления", True),
    ("ratio_error", "ratio_error", "ошибка i", True),
    ("contact_ratio", "contact_ratio", "перекрытие", True),
    ("warnings", "warnings", "предупреждения", False),
    ("folder", "folder", "папка", False),
    ("error", "error", "ошибка", False),
)
SUMMARY_COLUMNS = tuple(f[0] for f in SUMMARY_FIELDS)

# a warning's name in the summary, from the codes of the notes (the four the course grades first)
FLAGS = {
    "undercut": ("undercut", "подрезание"),
    "pressure_angle": ("pressure angle", "угол давления"),
    "ratio_error": ("ratio error", "ошибка передаточного отношения"),
    "contact_ratio": ("contact ratio", "коэффициент перекрытия"),
    "few_planets": ("few planets", "мало сателлитов"),
    "power": ("motor power", "мощность двигателя"),
    "pivot": ("rocker pivot", "ось коромысла"),
    "roller": ("roller", "ролик"),
    "book": ("the book's example", "пример пособия"),
    "drawing": ("drawing size", "размер чертежа"),
}
STATUS = {"ok": ("ok", "готово"), "failed": ("failed", "ошибка"), "not run": ("not run (interrupted)", "не выполнен (прервано)")}


def flag_of(code: str) -> str:
    """The summary name of a warning's code.

    >>> [flag_of(c) for c in ("undercut", "cam_undercut_convex", "cam_pressure_over", "eps_low", "x_y")]
    ['undercut', 'undercut', 'pressure_angle', 'contact_ratio', 'x_y']
    """
    if code == "undercut" or code.startswith("cam_undercut"):
        return "undercut"
    if code == "cam_pressure_over":
        return "pressure_angle"
    if code == "ratio_error":
        return "ratio_error"
    if code == "eps_low":
        return "contact_ratio"
    if code == "few_planets":
        return "few_planets"
    if code == "power_above_series":
        return "power"
    if code.startswith("cam_pivot"):
        return "pivot"
    if code.startswith("cam_roller"):
        return "roller"
    if code.startswith("book_"):
        return "book"
    if code.startswith("cam_drawing"):
        return "drawing"
    return code


def flag_name(flag: str, lang: str) -> str:
    en, ru = FLAGS.get(flag, (flag.replace("_", " "), flag.replace("_", " ")))
    return pick(lang, en, ru)


# ROSTER header names (English and what Russian teachers write) -> our keys
HEADER_ALIASES = {
    "student": ("student", "студент", "фио", "ф.и.о.", "ф. и. о.", "фамилия"),
    "variant": ("variant", "вариант", "вар", "вар."),
    "group": ("group", "группа"),
    "crank_rpm": ("crank_rpm", "n_кр", "n_kr", "nкр", "n кр"),
    "torque": ("torque", "torque_nm", "момент", "m_пр"),
}
ROSTER_COLUMNS = ("student", "variant", "group", "crank_rpm", "torque")


@record
class BatchJob:
    """One row of work: who, which variant (as given), the per-student inputs, its folder."""

    label: str
    variant: str
    crank_rpm: float | None = None
    torque_nm: float | None = None
    folder: str = ""  # relative to the output folder: variant-17 or Ivanov/variant-17
    group: str = ""
    fname: str = ""  # the student's file name (names.file_name), '' for a --variants run
    line: int = 0  # the roster line (rows are reported in roster order)


@record
class Roster:
    jobs: list
    bad: list
    path: Path
    encoding: str  # e.g. "cp1251 (Windows Cyrillic)"
    delimiter: str


@record
class BatchSummary:
    rows: tuple[dict, ...]
    failed: tuple[dict, ...] = field(default=())
    complete: bool = True
    not_run: int = 0


# --variants ------------------------------------------------------------------------------------


def parse_variant_spec(spec: str, known: set[int] | None = None) -> list[int]:
    """'1-68', '3,17,40', '1-4,17' -> sorted unique variant numbers, all in `known` (the table).

    The numbers outside the table are refused before anything is expanded or run, so
    ``1-10000000`` costs nothing.

    >>> parse_variant_spec("3,17,1-2")
    [1, 2, 3, 17]
    >>> parse_variant_spec("1-99", set(range(1, 69)))
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: --variants 1-99: 69-99 not in the table (it has variants 1-68); give numbers from 1 to 68
    """
    spec = str(spec)
    if len(spec) > limits.VARIANT_SPEC_CHARS:
        raise TmmError(f"--variants is {len(spec)} characters long, over {limits.VARIANT_SPEC_CHARS}; give ranges like 1-68")
    ranges = []
    for part in spec.split(","):
        part = part.strip()
        m = re.fullmatch(r"(\d{1,9})\s*-\s*(\d{1,9})", part)
        if m:
            lo, hi = int(m.group(1)), int(m.group(2))
            if lo > hi:
                raise TmmError(f"--variants range '{part}' runs backwards; write it as {hi}-{lo}")
            ranges.append((lo, hi))
        elif re.fullmatch(r"\d{1,9}", part):
            ranges.append((int(part), int(part)))
        else:
            shown = part if len(part) <= 20 and part.isprintable() else part[:20].encode("unicode_escape").decode() + "…"
            raise TmmError(f"--variants '{spec[:40]}' is not a list like 1-68 or 3,17,40; fix '{shown}'")
    if known is not None:
        lo_t, hi_t = min(known), max(known)
        outside = []
        for lo, hi in ranges:
            if hi < lo_t or lo > hi_t:
                outside.append((lo, hi))
            else:
                if lo < lo_t:
                    outside.append((lo, lo_t - 1))
                if hi > hi_t:
                    outside.append((hi_t + 1, hi))
        if outside:
            text = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in outside[:5])
            raise TmmError(f"--variants {spec[:40]}: {text} not in the table (it has variants {lo_t}-{hi_t}); "
                           f"give numbers from {lo_t} to {hi_t}")
        numbers = sorted({n for lo, hi in ranges for n in known if lo <= n <= hi})
        gaps = sorted({n for lo, hi in ranges if lo == hi for n in (lo,)} - set(numbers))
        if gaps:
            raise TmmError(f"--variants: variant {gaps[0]} is not in the table; choose from {lo_t} to {hi_t}")
    else:
        if sum(hi - lo + 1 for lo, hi in ranges) > limits.VARIANT_SPEC_COUNT:
            raise TmmError(f"--variants asks for over {limits.VARIANT_SPEC_COUNT} variants; give a shorter list")
        numbers = sorted({n for lo, hi in ranges for n in range(lo, hi + 1)})
    if len(numbers) > limits.VARIANT_SPEC_COUNT:
        raise TmmError(f"--variants asks for {len(numbers)} variants, over {limits.VARIANT_SPEC_COUNT}; split the batch")
    return numbers


def jobs_from_spec(spec: str, crank_rpm: float | None, torque_nm: float | None, variants_file=None) -> list[BatchJob]:
    from ..variants import load_table

    numbers = parse_variant_spec(spec, set(load_table(variants_file)))
    return [BatchJob(label=f"variant {n}", variant=str(n), crank_rpm=crank_rpm, torque_nm=torque_nm, folder=f"variant-{n:02d}")
            for n in numbers]


# --roster --------------------------------------------------------------------------------------


def _header_key(cell: str) -> str:
    from ..inputs.names import clean_text

    h = clean_text(cell).lower()
    h = re.split(r"\s*[\[(]|,\s", h)[0].strip()
    for key, names in HEADER_ALIASES.items():
        if h in names:
            return key
    return h


def _opt(raw: str, name: str, default, lo, hi):
    raw = (raw or "").strip()
    if not raw:
        return default
    from ..inputs.tables import parse_number

    value = parse_number(raw, name)
    return limits.check_range(value, lo, hi, name)


def jobs_from_roster(path: str | Path, crank_rpm: float | None, torque_nm: float | None, variants_file=None) -> Roster:
    """Read a roster (student,variant[,group][,crank_rpm][,torque], English or Russian headers).

    A bad row (no name, a variant not in the table, a value out of range, two names sharing one
    file name) is returned with its reason among `bad`; a file without the student and variant
    columns, over the size limits, or not text, is an error for the whole roster.
    """
    from ..inputs.tables import delimiter, read_text, rows
    from ..variants import load_table

    src = read_text(path, f"roster {path}", limits.ROSTER_BYTES)
    table = load_table(variants_file)
    lines = rows(src.text, limits.ROSTER_ROWS, f"roster {path}")
    first = next((i for i, r in enumerate(lines) if r), None)
    header = [_header_key(h) for h in (lines[first] if first is not None else [])]
    missing = [c for c in ("student", "variant") if c not in header]
    if missing:
        raise TmmError(f"roster {path} has no column(s) {', '.join(missing)}; the header must be "
                       f"student,variant[,group][,crank_rpm][,torque] (or студент;вариант;группа;n_кр;момент)")
    col = {k: header.index(k) for k in ROSTER_COLUMNS if k in header}
    jobs: list[BatchJob] = []
    bad: list[dict] = []
    seen: dict[str, tuple[int, str]] = {}
    for lineno, raw in enumerate(lines[first + 1:], start=first + 2):
        if not raw:
            continue
        cell = {k: (raw[i] if i < len(raw) else "").strip() for k, i in col.items()}
        student = display_name(cell["student"])
        group = display_name(cell.get("group", ""))
        label = student or f"line {lineno}"
        variant = cell["variant"][:10]
        try:
            if not student:
                raise TmmError("the student column is empty")
            if not variant:
                raise TmmError("the variant column is empty")
            if not variant.isdigit() or int(variant) not in table:
                raise TmmError(f"variant {variant} is not in the table; choose a variant from {min(table)} to {max(table)}")
            crank = _opt(cell.get("crank_rpm"), "crank_rpm", crank_rpm, *limits.CRANK_RPM)
            torque = _opt(cell.get("torque"), "torque", torque_nm, *limits.TORQUE_NM)
            fname = file_name(student)
            if not fname:
                raise TmmError("the name has no letter or digit to name a file by")
            key = collision_key(fname)
            if key in seen:
                line0, name0 = seen[key]
                raise TmmError(f"'{student}' gives the same file name '{fname}' as '{name0}' on line {line0} "
                               f"(names differing only in case or punctuation share one file); make the names differ")
            seen[key] = (lineno, student)
        except TmmError as exc:
            bad.append(_failure_row(BatchJob(label=label, variant=variant, group=group, line=lineno),
                                    f"roster line {lineno}: {exc}"))
            continue
        n = int(variant)
        jobs.append(BatchJob(label=student, variant=str(n), crank_rpm=crank, torque_nm=torque,
                             folder=f"{fname}/variant-{n:02d}", group=group, fname=fname, line=lineno))
    if not jobs and not bad:
        raise TmmError(f"roster {path} has a header but no students; add one row per student")
    return Roster(jobs, bad, Path(path), src.encoding_name, delimiter(src.text))


# rows ------------------------------------------------------------------------------------------


def _failure_row(job: BatchJob, reason: str, status: str = "failed") -> dict:
    row = {c: "" for c in SUMMARY_COLUMNS}
    row.update(student=job.label, group=job.group, variant=job.variant, status=status, error=reason, warnings=(),
               line=job.line)
    return row


def summary_row(job: BatchJob, doc: dict, folder: str, codes=()) -> dict:
    """One summary row from a project JSON document (the content of results.json) and the codes
    of its warnings (`result.notes`)."""
    g, c = doc["gears"], doc["cam"]
    pl = g["planetary"]
    stages = pl["stages"]
    teeth = " + ".join(
        "/".join(str(s[k]) for k in ("z_sun", "z_planet", "z_planet2", "z_ring") if s.get(k) is not None)
        for s in stages
    )
    planets = "+".join(str(s["planets"]) for s in stages)
    pa = c["pressure_angle_max_deg"]
    flags = tuple(dict.fromkeys(flag_of(code) for code in codes))
    row = {
        "student": job.label,
        "group": job.group,
        "variant": doc["variant"],
        "scheme": doc["input"]["scheme"],
        "law": doc["input"]["law"],
        "status": "ok",
        "crank_rpm": g["crank_rpm"],
        "n_motor_rpm": g["motor"]["n_rpm"],
        "power_kw": g["motor"].get("power_kw"),
        "i_spur": g["i_spur"],
        "i_planetary": g["i_planetary"],
        "planetary_scheme": pl["scheme"],
        "teeth": teeth,
        "planets": planets,
        "ratio_error_pct": pl["ratio_error_pct"],
        "z1": g["spur"]["z1"],
        "z2": g["spur"]["z2"],
        "eps_alpha": g["spur"]["eps_alpha"],
        "r0_mm": c["r0_mm"],
        "e_mm": c.get("e_mm"),
        "l_oc_mm": c.get("l_oc_mm"),
        "roller_mm": c.get("roller_mm"),
        "nu_rise_deg": pa.get("rise"),
        "nu_return_deg": pa.get("return"),
        **{k: int(k in flags) for k in ("undercut", "pressure_angle", "ratio_error", "contact_ratio")},
        "warnings": flags,
        "folder": folder,
        "error": "",
        "line": job.line,
    }
    return row


_FIGURE_CACHE: dict = {}  # per worker process: drawings shared by rows (the reducer's at one crank speed, a spur mesh)
_FIGURE_CACHE_SIZE = 48  # drawings kept, the least recently used dropped first (a few MB; a roster stays small)
_SHARED: list = []  # this worker's SharedFigures: the same drawings, between the batch's workers


def _worker_start(shared_root: str | None) -> None:
    """Initializer of a batch worker process: signals (interrupt.worker_init) and the batch's
    folder of shared drawings."""
    from ..output.interrupt import worker_init

    worker_init()
    _SHARED.clear()
    if shared_root:
        from ..render.figures.shared import SharedFigures

        _SHARED.append(SharedFigures(shared_root))


def run_job(job: BatchJob, out_dir: str, variants_file: str | None, lang: str, fmt: str, plots: bool, report: str | None,
            sheets: bool = False) -> dict:
    """Run one row in this process: the project, its folder, its summary row (or a failure row)."""
    from ..project import run_project
    from ..render.project import write_project_folder
    from ..inputs.titleblock import TitleFields
    from ..variants import get_variant

    try:
        v = get_variant(job.variant, variants_file)
        result = run_project(v, crank_rpm=job.crank_rpm, torque_nm=job.torque_nm)
        folder = Path(out_dir) / job.folder
        title = TitleFields(student=job.label, group=job.group) if job.fname else None
        doc, _ = write_project_folder(result, folder, lang, fmt=fmt, plots=plots, report=report,
                                      figure_cache=_FIGURE_CACHE, title=title, sheets=sheets,
                                      shared_figures=_SHARED[0] if _SHARED else None)
        while len(_FIGURE_CACHE) > _FIGURE_CACHE_SIZE:
            _FIGURE_CACHE.pop(next(iter(_FIGURE_CACHE)))
        codes = [n.code for n in result.notes if n.level == "warning"]
        return summary_row(job, doc, str(folder), codes)
    except TmmError as exc:
        return _failure_row(job, str(exc))
    except Exception as exc:  # a bug must not stop the class's batch; it is reported in its row
        return _failure_row(job, f"internal error {exc.__class__.__name__}: {exc}")


def summary_csv(rows: list[dict], lang: str, csv_locale: str) -> bytes:
    """summary.csv: headers and status in `lang`; ';' and decimal commas under the ru CSV locale."""
    from ..inputs.tables import csv_encoding, csv_text

    header = [pick(lang, en, ru) for _, en, ru, _ in SUMMARY_FIELDS]
    numeric = {i for i, f in enumerate(SUMMARY_FIELDS) if f[3]}
    body = []
    for r in rows:
        cells = []
        for key, *_ in SUMMARY_FIELDS:
            v = r.get(key)
            if key == "status":
                v = pick(lang, *STATUS.get(v, (v, v)))
            elif key == "warnings":
                v = ", ".join(flag_name(f, lang) for f in (v or ()))
            cells.append(v)
        body.append(cells)
    return csv_text(header, body, numeric, csv_locale).encode(csv_encoding(csv_locale))


def write_summary_csv(path: Path, rows: list[dict], lang: str = "en", csv_locale: str = "en") -> None:
    """summary.csv, written atomically and recorded in the folder's manifest."""
    from ..output.folder import write_owned

    path = Path(path)
    write_owned(path.parent, path.name, summary_csv(rows, lang, csv_locale))


# the run ---------------------------------------------------------------------------------------


def prepare_out_dir(out_dir: Path, jobs: list[BatchJob]) -> None:
    """Before any work: refuse a foreign summary.csv, remove the folders of the previous batch
    run (only the files tmm wrote) and the old summary, record the folders this run will write."""
    from ..output.folder import refuse_foreign, make_dirs, read_manifest, remove_written_tree, write_manifest

    make_dirs(out_dir)
    man = read_manifest(out_dir)
    refuse_foreign(out_dir, ["summary.csv"], man["files"])
    for rel in sorted(man["dirs"]):
        remove_written_tree(out_dir, rel)
    files = set(man["files"])
    if "summary.csv" in files and (out_dir / "summary.csv").is_file() and not (out_dir / "summary.csv").is_symlink():
        (out_dir / "summary.csv").unlink()
    files.discard("summary.csv")
    write_manifest(out_dir, files, {j.folder for j in jobs})


def _cleanup_after_stop(out_dir: Path, jobs: list[BatchJob], done: set[int], dead_pids=()) -> None:
    """After the workers were stopped: their staging folders, and the folders of rows whose result
    never reached the summary (a worker killed while moving its files in, or just after), so the
    summary describes exactly the folders beside it."""
    from ..output.folder import MANIFEST, remove_stale_staging, remove_temp_file, remove_written_tree

    parents = {out_dir} | {(out_dir / j.folder).parent for j in jobs}
    for p in parents:
        remove_stale_staging(p, only_dead=True, dead_pids=set(dead_pids))
    for folder in parents | {out_dir / j.folder for j in jobs}:  # a worker killed while writing a manifest
        for pid in dead_pids:
            remove_temp_file(folder / f".{MANIFEST}.tmp-{pid}")
    for i, j in enumerate(jobs):
        if i not in done:
            remove_written_tree(out_dir, j.folder)
            if "/" in j.folder:
                try:
                    os.rmdir(out_dir / j.folder.split("/")[0])
                except OSError:
                    pass


def _stop_pool(pool) -> list[int]:
    """Stop the worker processes now: SIGTERM (they remove their staging folder), then SIGKILL;
    returns their pids."""
    import time

    procs = list((getattr(pool, "_processes", None) or {}).values())
    for p in procs:
        try:
            p.terminate()
        except Exception:
            pass
    deadline = time.monotonic() + 1.0
    for p in procs:
        p.join(max(0.0, deadline - time.monotonic()))
    for p in procs:
        if p.is_alive():
            p.kill()
            p.join(1.0)
    pool.shutdown(wait=False, cancel_futures=True)
    return [p.pid for p in procs]


def run_batch(jobs: list[BatchJob], bad: list[dict], out_dir: Path, *, variants_file: str | None = None,
              lang: str = "en", fmt: str = "png", plots: bool = True, report: str | None = "md",
              jobs_n: int | None = None, progress: bool = False, csv_locale: str | None = None,
              sheets: bool = False) -> BatchSummary:
    """Run all jobs (in `jobs_n` processes), write out_dir/summary.csv, return the rows in order.

    On Ctrl-C or SIGTERM (:class:`tmm_cli.output.interrupt.Interrupted`) the workers are stopped, the
    summary of the finished rows is written with the rest marked "not run", and Interrupted is
    raised again with a message saying so.
    """
    csv_locale = csv_locale or lang
    out_dir = Path(out_dir)
    if variants_file is not None:  # fail once, early, on a broken table rather than in every row
        from ..variants import load_table

        load_table(variants_file)
    from ..output.folder import lock_dir, make_dirs

    created = make_dirs(out_dir)
    try:
        with lock_dir(out_dir, wait=False, what="tmm batch"):  # two batches never mix one folder
            prepare_out_dir(out_dir, jobs)
            return _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale, sheets)
    except TmmError:
        from ..output.folder import remove_empty_dirs

        remove_empty_dirs(created)
        raise


def _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale, sheets) -> BatchSummary:
    import signal

    from ..output.interrupt import Interrupted

    n_workers = max(1, min(jobs_n or os.cpu_count() or 1, len(jobs) or 1))
    args = (str(out_dir), variants_file, lang, fmt, plots, report, sheets)
    results: dict[int, dict] = {}
    stopped: KeyboardInterrupt | None = None

    # what every row needs, loaded once here (forked workers share it; the collector is calmed)
    from .. import project  # noqa: F401

    if plots:
        from ..render.project import prepare_figures

        prepare_figures(svg=report == "pdf")
    bar = None
    if progress:
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        bar = Progress(TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), transient=False)
        task = bar.add_task("tmm batch", total=len(jobs))
    pool = shared_root = None
    try:
        if n_workers == 1:
            if bar is not None:
                bar.start()
            for i, job in enumerate(jobs):
                results[i] = run_job(job, *args)
                if bar is not None:
                    bar.advance(task)
        else:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor, as_completed

            ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else None
            if plots:  # drawings one worker made serve the others (render/shared_figures), removed below
                import tempfile

                shared_root = tempfile.mkdtemp(prefix="tmm-figures-")
            pool = ProcessPoolExecutor(max_workers=n_workers, mp_context=ctx, initializer=_worker_start,
                                       initargs=(shared_root,))
            futures = {pool.submit(run_job, job, *args): i for i, job in enumerate(jobs)}
            if bar is not None:  # its refresh thread only now: the workers are forked at the first submit,
                bar.start()      # and a fork beside a running thread can inherit a lock it holds
            for fut in as_completed(futures):
                i = futures[fut]
                try:
                    results[i] = fut.result()
                except Exception as exc:  # a crashed worker: report the row, go on
                    results[i] = _failure_row(jobs[i], f"worker failed: {exc.__class__.__name__}: {exc}")
                if bar is not None:
                    bar.advance(task)
            pool.shutdown(wait=True)
    except KeyboardInterrupt as exc:
        stopped = exc
        try:  # a second Ctrl-C must not cut the clean-up short
            old = {s: signal.signal(s, signal.SIG_IGN) for s in (signal.SIGINT, signal.SIGTERM)}
        except ValueError:  # not the main thread
            old = {}
        try:
            pids = _stop_pool(pool) if pool is not None else []
            _cleanup_after_stop(out_dir, jobs, set(results), pids)
        finally:
            for s, h in old.items():
                signal.signal(s, h)
    finally:
        if bar is not None:
            bar.stop()
        if shared_root is not None:
            import shutil

            shutil.rmtree(shared_root, ignore_errors=True)
    rows = list(bad) + [results.get(i) or _failure_row(job, "", status="not run") for i, job in enumerate(jobs)]
    rows.sort(key=lambda r: r.get("line") or 0)  # roster order (stable: --variants rows keep theirs)
    write_summary_csv(out_dir / "summary.csv", rows, lang, csv_locale)
    failed = tuple(r for r in rows if r["status"] != "ok")
    not_run = sum(r["status"] == "not run" for r in rows)
    if stopped is not None:
        signum = getattr(stopped, "signum", signal.SIGINT)
        done = len(jobs) - not_run
        raise Interrupted(signum, pick(lang, f"interrupted: {done} of {len(jobs)} rows finished; "
                                             f"{out_dir / 'summary.csv'} lists them and marks the rest not run",
                                       f"прервано: выполнено {done} из {len(jobs)}; {out_dir / 'summary.csv'} "
                                       f"перечисляет их, остальные отмечены как не выполненные"))
    return BatchSummary(rows=tuple(rows), failed=failed, complete=True, not_run=0)
