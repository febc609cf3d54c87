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
from dataclasses import field
from pathlib import Path

from ..errors import TmmError
from ..i18n import tr
from ..records import record
from .roster import BatchJob
from .summary import failure_row, summary_row, write_summary_csv


@record
class BatchSummary:
    rows: tuple[dict, ...]
    failed: tuple[dict, ...] = field(default=())
    complete: bool = True
    not_run: int = 0


# --variants ------------------------------------------------------------------------------------


# --roster --------------------------------------------------------------------------------------


# rows ------------------------------------------------------------------------------------------


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


def _linkage(path: str):
    """Sheets 1–2 of a roster row's mechanism file (the row fails with the file's error)."""
    from ..inputs.mechanism import read_mechanism_tables
    from ..project import analyse_linkage

    return analyse_linkage(read_mechanism_tables(path), Path(path).name)


def job_title(job: BatchJob, base=None):
    """The title block of one row: the student and group of the roster row, the teacher, the
    organisation and the year the whole group shares (`base`: tmm.toml and --teacher/--org; its
    group is the default of a row without one). None when there is nothing to print.

    >>> from tmm_cli.inputs.titleblock import TitleFields
    >>> t = job_title(BatchJob("Иванов", "17", fname="Иванов"), TitleFields(teacher="Петров П. П.", group="П-243"))
    >>> t.student, t.group, t.teacher
    ('Иванов', 'П-243', 'Петров П. П.')
    >>> job_title(BatchJob("variant 17", "17")) is None
    True
    """
    from dataclasses import replace

    from ..inputs.titleblock import TitleFields

    base = base or TitleFields()
    shared = replace(TitleFields(), teacher=base.teacher, org=base.org, year=base.year, group=base.group)
    if job.fname:
        return replace(shared, student=job.label, group=job.group or base.group)
    return shared if (shared.teacher or shared.org or shared.group) else None


def run_job(job: BatchJob, out_dir: str, variants_file: str | None, lang: str, fmt: str, plots: bool, report: str | None,
            sheets: bool = False, title_base=None) -> dict:
    """Run one row in this process: the project, its folder, its summary row (or a failure row)."""
    from ..project import run_project
    from ..render.project import write_project_folder
    from ..variants import get_variant

    try:
        v = get_variant(job.variant, variants_file)
        linkage = _linkage(job.mechanism) if job.mechanism else None
        result = run_project(v, crank_rpm=job.crank_rpm, torque_nm=job.torque_nm, linkage=linkage,
                             linkage_name=Path(job.mechanism).name if job.mechanism else "")
        folder = Path(out_dir) / job.folder
        title = job_title(job, title_base)
        doc, _ = write_project_folder(result, folder, lang, fmt=fmt, plots=plots, report=report,
                                      figure_cache=_FIGURE_CACHE, title=title, sheets=sheets,
                                      shared_figures=_SHARED[0] if _SHARED else None)
        while len(_FIGURE_CACHE) > _FIGURE_CACHE_SIZE:
            _FIGURE_CACHE.pop(next(iter(_FIGURE_CACHE)))
        codes = [n.code for n in result.notes if n.level == "warning"]
        return summary_row(job, doc, str(folder), codes)
    except TmmError as exc:
        return failure_row(job, str(exc))
    except Exception as exc:  # a bug must not stop the class's batch; it is reported in its row
        return failure_row(job, f"internal error {exc.__class__.__name__}: {exc}")


# the run ---------------------------------------------------------------------------------------


def prepare_out_dir(out_dir: Path, jobs: list[BatchJob]) -> None:
    """Before any work: refuse a foreign summary.csv, remove the folders of the previous batch
    run (only the files tmm wrote) and the old summary, record the folders this run will write."""
    from ..output.folder import (
        make_dirs,
        read_manifest,
        refuse_foreign,
        remove_written_tree,
        write_manifest,
    )

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
    # (group.html stays until the new one replaces it: it is written with summary.csv)


def _cleanup_after_stop(out_dir: Path, jobs: list[BatchJob], done: set[int], dead_pids=()) -> None:
    """After the workers were stopped: their staging folders, and the folders of rows whose result
    never reached the summary (a worker killed while moving its files in, or just after), so the
    summary describes exactly the folders beside it."""
    from ..output.folder import (
        MANIFEST,
        remove_stale_staging,
        remove_temp_file,
        remove_written_tree,
    )

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
              sheets: bool = False, title=None) -> BatchSummary:
    """Run all jobs (in `jobs_n` processes), write out_dir/summary.csv, return the rows in order.

    On Ctrl-C or SIGTERM (:class:`tmm_cli.output.interrupt.Interrupted`) the workers are stopped, the
    summary of the finished rows is written with the rest marked "not run", and Interrupted is
    raised again with a message saying so.

    `title` (TitleFields: tmm.toml and --teacher/--org) gives every row's title block the
    teacher, the organisation and the year; the student and group come from the roster row.
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
            return _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale, sheets,
                        title)
    except TmmError:
        from ..output.folder import remove_empty_dirs

        remove_empty_dirs(created)
        raise


def _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale, sheets,
         title=None) -> BatchSummary:
    import signal

    from ..output.interrupt import Interrupted

    n_workers = max(1, min(jobs_n or os.cpu_count() or 1, len(jobs) or 1))
    args = (str(out_dir), variants_file, lang, fmt, plots, report, sheets, title)
    results: dict[int, dict] = {}
    stopped: KeyboardInterrupt | None = None

    # what every row needs, loaded once here (forked workers share it; the collector is calmed)
    from .. import project  # noqa: F401

    if plots:
        from ..render.figures.pipeline import prepare_figures

        prepare_figures(svg=report == "pdf")
    bar = None
    if progress:
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeElapsedColumn,
        )

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
            if plots:  # drawings one worker made serve the others (render/figures/shared.py), removed below
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
                    results[i] = failure_row(jobs[i], f"worker failed: {exc.__class__.__name__}: {exc}")
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
    rows = [failure_row(b.job, b.reason) for b in bad] + [results.get(i) or failure_row(job, "", status="not run") for i, job in enumerate(jobs)]
    rows.sort(key=lambda r: r.get("line") or 0)  # roster order (stable: --variants rows keep theirs)
    write_summary_csv(out_dir / "summary.csv", rows, lang, csv_locale)
    from .group import write_batch_page

    write_batch_page(out_dir, rows, lang)  # group.html: the same rows, with links and the group's statistics
    failed = tuple(r for r in rows if r["status"] != "ok")
    not_run = sum(r["status"] == "not run" for r in rows)
    if stopped is not None:
        signum = getattr(stopped, "signum", signal.SIGINT)
        done = len(jobs) - not_run
        raise Interrupted(signum, tr(lang, "interrupted: {done} of {jobs} rows finished; {v} lists them and marks the rest not run").format(done=done, jobs=len(jobs), v=out_dir / 'summary.csv'))
    return BatchSummary(rows=tuple(rows), failed=failed, complete=True, not_run=0)
