"""Teachers' batch: many variants or a class roster, run in parallel, one summary row each.

A failing row never stops the batch: it becomes a row with its reason, and so does a row whose
worker process died (teacher/workers.py: the other rows go on). The summary row is read from the
same JSON document that ``results.json`` holds, so the summary can never disagree with the
per-variant folders. The output folder's manifest records the folders of the last batch run: a
new run first removes them (only the files the batch wrote, unchanged since), so ``summary.csv``
always describes exactly the folders beside it, and two rosters or runs are never mixed. A batch
never takes over a folder another command wrote (`tmm project --out` the same folder), never
writes through a student folder that is a link, and a batch with no row to run changes nothing.
Ctrl-C, SIGTERM or SIGHUP stop the workers at once; the summary then lists what finished and
marks the rest "not run".
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
    summary_path: str = ""  # '' when nothing ran (and nothing was written)
    kept: tuple = ()  # files of the user's met (a summary.csv the teacher edited): output/folder.Kept


# rows ------------------------------------------------------------------------------------------


_FIGURE_CACHE: dict = {}  # per worker process: drawings shared by rows (the reducer's at one crank speed, a spur mesh)
_FIGURE_CACHE_SIZE = 48  # drawings kept, the least recently used dropped first (a few MB; a roster stays small)
_SHARED: list = []  # this worker's SharedFigures: the same drawings, between the batch's workers
WRITER = "batch"  # the batch's name in the manifests of the folders it writes


def _worker_start(parent_pid: int | None, shared_root: str | None) -> None:
    """Initializer of a batch worker process: signals (interrupt.worker_init; if the batch dies,
    the worker removes the shared drawings the batch can no longer remove) and the batch's folder
    of shared drawings."""
    from ..output.interrupt import worker_init

    orphaned = ()
    if shared_root:
        import shutil

        orphaned = (lambda: shutil.rmtree(shared_root, ignore_errors=True),)
    worker_init(parent_pid, orphaned)
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
        kept: list = []
        doc, _ = write_project_folder(result, folder, lang, fmt=fmt, plots=plots, report=report,
                                      figure_cache=_FIGURE_CACHE, title=title, sheets=sheets,
                                      shared_figures=_SHARED[0] if _SHARED else None, writer=WRITER,
                                      kept=kept, root=Path(out_dir))
        while len(_FIGURE_CACHE) > _FIGURE_CACHE_SIZE:
            _FIGURE_CACHE.pop(next(iter(_FIGURE_CACHE)))
        codes = [n.code for n in result.notes if n.level == "warning"]
        row = summary_row(job, doc, str(folder), codes)
        if kept:
            row["kept"] = tuple(kept)
        return row
    except TmmError as exc:
        return failure_row(job, str(exc))
    except Exception as exc:  # a bug must not stop the class's batch; it is reported in its row
        return failure_row(job, f"internal error {exc.__class__.__name__}: {exc}")


# the run ---------------------------------------------------------------------------------------


def prepare_out_dir(out_dir: Path, jobs: list[BatchJob]) -> list[str]:
    """Before any work: refuse a foreign summary.csv and a folder another command wrote where a
    row is to go; remove the folders of the previous batch run (only the files the batch wrote,
    unchanged since) and the old summary (unless the user changed it), record the folders this
    run will write. Returns the folders of rows that cannot be written (a link on the way)."""
    from ..output.folder import (
        check_inside,
        folder_writers,
        make_dirs,
        read_manifest,
        refuse_foreign,
        remove_written_tree,
        unchanged,
        write_manifest,
    )

    make_dirs(out_dir)
    man = read_manifest(out_dir)
    refuse_foreign(out_dir, ["summary.csv"], man["files"])
    blocked = []
    for j in jobs:
        try:
            check_inside(out_dir, out_dir / j.folder)
        except TmmError:
            blocked.append(j.folder)
            continue
        if j.folder in man["dirs"]:
            continue
        others = folder_writers(out_dir / j.folder) - {WRITER}
        if others:
            who = ", ".join(f"tmm {w}" for w in sorted(others) if w != "?") or "tmm"
            raise TmmError(f"{out_dir / j.folder} holds the results of {who}, not of a batch; a batch never takes "
                           f"over such a folder: choose another --out for the batch")
    for rel in sorted(man["dirs"]):
        remove_written_tree(out_dir, rel, WRITER)
    entries = dict(man["entries"])
    summary = out_dir / "summary.csv"
    if "summary.csv" in entries and unchanged(summary, entries["summary.csv"]):
        summary.unlink()
        del entries["summary.csv"]
    write_manifest(out_dir, set(entries), {j.folder for j in jobs}, entries)
    # (group.html stays until the new one replaces it: it is written with summary.csv)
    return blocked


def _sweep(out_dir: Path, jobs: list[BatchJob], rows, dead_pids) -> None:
    """After workers died or were stopped: their staging folders and temporary files, and the
    folders of `rows` whose result never reached the summary (a worker killed while moving its
    files in, or just after), so the summary describes exactly the folders beside it."""
    from ..output.folder import remove_stale_staging, remove_written_tree

    dead = set(dead_pids)
    places = {out_dir} | {(out_dir / j.folder).parent for j in jobs} | {out_dir / jobs[i].folder for i in rows}
    for p in places:
        remove_stale_staging(p, only_dead=True, dead_pids=dead)
    for i in rows:
        j = jobs[i]
        remove_written_tree(out_dir, j.folder, WRITER)
        if "/" in j.folder:
            try:
                os.rmdir(out_dir / j.folder.split("/")[0])
            except OSError:
                pass


def _death_reason(code: int | None) -> str:
    """Why a worker ended, from its exit code: "killed by SIGKILL", "exit status 1".

    >>> _death_reason(-9), _death_reason(143), _death_reason(1)
    ('killed by SIGKILL', 'killed by SIGTERM', 'exit status 1')
    """
    import signal

    from ..output.interrupt import EXIT_CODES

    by_code = {c: s for s, c in EXIT_CODES.items()}
    if code is not None and code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    if code in by_code:
        return f"killed by {signal.Signals(by_code[code]).name}"
    return f"exit status {code}"


def run_batch(jobs: list[BatchJob], bad: list, out_dir: Path, *, variants_file: str | None = None,
              lang: str = "en", fmt: str = "png", plots: bool = True, report: str | None = "md",
              jobs_n: int | None = None, progress: bool = False, csv_locale: str | None = None,
              sheets: bool = False, title=None, force: bool = False, say=None,
              start_method: str | None = None) -> BatchSummary:
    """Run all jobs (in `jobs_n` processes), write out_dir/summary.csv, return the rows in order.

    With no job to run (every roster row has an error) nothing in `out_dir` is touched: the rows
    come back with their reasons and no summary is written. `say(text)` is told of a stale lock
    taken over. `start_method` ('fork', 'spawn') overrides the platform's (teacher/workers.py).

    On Ctrl-C, SIGTERM or SIGHUP (:class:`tmm_cli.output.interrupt.Interrupted`) the workers are
    stopped, the summary of the finished rows is written with the rest marked "not run", and
    Interrupted is raised again with a message saying so.

    `title` (TitleFields: tmm.toml and --teacher/--org) gives every row's title block the
    teacher, the organisation and the year; the student and group come from the roster row.
    """
    csv_locale = csv_locale or lang
    out_dir = Path(out_dir)
    if variants_file is not None:  # fail once, early, on a broken table rather than in every row
        from ..variants import load_table

        load_table(variants_file)
    if not jobs:  # nothing to run: the earlier results stay as they are
        rows = sorted((failure_row(b.job, b.reason) for b in bad), key=lambda r: r.get("line") or 0)
        return BatchSummary(rows=tuple(rows), failed=tuple(rows))
    from ..output.folder import make_dirs, remove_empty_dirs
    from ..output.lock import batch_lock

    def stale(pid: int) -> None:
        if say is not None:
            say(tr(lang, "took over the lock of {out}: the tmm batch that held it (process {pid}) is gone").format(
                out=out_dir, pid=pid))

    created = make_dirs(out_dir)
    try:
        with batch_lock(out_dir, what="tmm batch", say=stale):  # two batches never mix one folder
            blocked = prepare_out_dir(out_dir, jobs)
            return _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale,
                        sheets, force, blocked, start_method, title)
    except TmmError:
        remove_empty_dirs(created)
        raise


def _run(jobs, bad, out_dir, variants_file, lang, fmt, plots, report, jobs_n, progress, csv_locale, sheets, force,
         blocked, start_method, title=None) -> BatchSummary:
    import signal

    from ..output.interrupt import STOPPING, Interrupted

    args = (str(out_dir), variants_file, lang, fmt, plots, report, sheets, title)
    results: dict[int, dict] = {}
    for i, job in enumerate(jobs):  # a link on the way to the row's folder: the row fails, nothing is written
        if job.folder in blocked:
            results[i] = failure_row(job, f"{out_dir / job.folder.split('/')[0]} is a symbolic link or not a folder; "
                                          f"a batch writes only into real folders inside {out_dir}")
    todo = [i for i in range(len(jobs)) if i not in results]
    n_workers = max(1, min(jobs_n or os.cpu_count() or 1, len(todo) or 1))
    stopped: KeyboardInterrupt | None = None

    # what every row needs, loaded once here (forked workers share it; the collector is calmed)
    from .. import project  # noqa: F401

    if plots:
        from ..render.figures.pipeline import prepare_figures

        from ..render.project import report_formats

        prepare_figures(set(), note=bool(report_formats(report) & {"pdf", "docx"}))
    bar = None
    if progress:
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            TextColumn,
            TimeElapsedColumn,
        )

        # refreshed at each row, never by a thread: a worker forked beside a thread could inherit a lock it holds
        bar = Progress(TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                       transient=False, auto_refresh=False)
        task = bar.add_task("tmm batch", total=len(todo))

    def advance():
        if bar is not None:
            bar.update(task, advance=1, refresh=True)

    workers = shared_root = None
    try:
        if bar is not None:
            bar.start()
        if n_workers == 1:
            for i in todo:
                results[i] = run_job(jobs[i], *args)
                advance()
        else:
            from ..output.lock import held_descriptors
            from .workers import Workers

            if plots:  # drawings one worker made serve the others (render/figures/shared.py), removed below
                import tempfile

                shared_root = tempfile.mkdtemp(prefix="tmm-figures-")
            workers = Workers(n_workers, run_job, _worker_start, (shared_root,), method=start_method,
                              inherit=held_descriptors())

            def on_result(k: int, row: dict) -> None:
                results[todo[k]] = row
                advance()

            def on_death(k: int, code, pid: int) -> None:
                i = todo[k]
                results[i] = failure_row(jobs[i], f"the worker process running this row stopped "
                                                  f"({_death_reason(code)}); the other rows went on")
                _sweep(out_dir, jobs, [i], [pid])
                advance()

            workers.run([(jobs[i], *args) for i in todo], on_result, on_death)
            _sweep(out_dir, jobs, [], workers.dead_pids)
    except KeyboardInterrupt as exc:
        stopped = exc
        try:  # a second Ctrl-C must not cut the clean-up short
            old = {s: signal.signal(s, signal.SIG_IGN) for s in STOPPING}
        except ValueError:  # not the main thread
            old = {}
        try:
            pids = workers.stop() if workers is not None else []
            _sweep(out_dir, jobs, [i for i in range(len(jobs)) if i not in results], pids)
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
    kept: list = []
    path = write_summary_csv(out_dir / "summary.csv", rows, lang, csv_locale, writer=WRITER, force=force, kept=kept)
    from .group import write_batch_page

    write_batch_page(out_dir, rows, lang)  # group.html: the same rows, with links and the group's statistics
    failed = tuple(r for r in rows if r["status"] != "ok")
    not_run = sum(r["status"] == "not run" for r in rows)
    if stopped is not None:
        signum = getattr(stopped, "signum", signal.SIGINT)
        done = len(jobs) - not_run
        raise Interrupted(signum, tr(lang, "interrupted: {done} of {jobs} rows finished; {v} lists them and marks the rest "
                                           "not run").format(done=done, jobs=len(jobs), v=path))
    return BatchSummary(rows=tuple(rows), failed=failed, complete=True, not_run=0, summary_path=str(path), kept=tuple(kept))
