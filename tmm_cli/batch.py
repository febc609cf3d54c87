"""Teachers' batch: many variants or a class roster, run in parallel, one summary row each.

A failing row never stops the batch: it becomes a row with its reason. The summary row is read
from the same JSON document that ``results.json`` holds, so the summary can never disagree with
the per-variant folders.
"""

from __future__ import annotations

import csv
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from .errors import TmmError

ROSTER_COLUMNS = ("student", "variant", "crank_rpm", "torque")

SUMMARY_COLUMNS = (
    "student", "variant", "scheme", "law", "status", "crank_rpm", "n_motor_rpm", "power_kw",
    "i_spur", "i_planetary", "planetary_scheme", "teeth", "planets", "ratio_error_pct",
    "z1", "z2", "eps_alpha", "r0_mm", "e_mm", "l_oc_mm", "roller_mm",
    "nu_rise_deg", "nu_return_deg", "warnings", "folder", "error",
)


@dataclass(frozen=True)
class BatchJob:
    """One row of work: who, which variant (as given), and the per-student inputs."""

    label: str
    variant: str
    crank_rpm: float | None = None
    torque_nm: float | None = None
    folder: str = ""


@dataclass(frozen=True)
class BatchSummary:
    rows: tuple[dict, ...]
    failed: tuple[dict, ...] = field(default=())


def parse_variant_spec(spec: str) -> list[int]:
    """'1-68', '3,17,40', '1-4,17' -> sorted unique variant numbers.

    >>> parse_variant_spec("3,17,1-2")
    [1, 2, 3, 17]
    """
    numbers: set[int] = set()
    for part in str(spec).split(","):
        part = part.strip()
        m = re.fullmatch(r"(\d+)\s*-\s*(\d+)", part)
        if m:
            lo, hi = int(m.group(1)), int(m.group(2))
            if lo > hi:
                raise TmmError(f"--variants range '{part}' runs backwards; write it as {hi}-{lo}")
            numbers.update(range(lo, hi + 1))
        elif part.isdigit():
            numbers.add(int(part))
        else:
            raise TmmError(f"--variants '{spec}' is not a list like 1-68 or 3,17,40; fix '{part}'")
    return sorted(numbers)


def jobs_from_spec(spec: str, crank_rpm: float | None, torque_nm: float | None) -> list[BatchJob]:
    return [
        BatchJob(label=f"variant {n}", variant=str(n), crank_rpm=crank_rpm, torque_nm=torque_nm, folder=f"variant-{n:02d}")
        for n in parse_variant_spec(spec)
    ]


def _slug(text: str) -> str:
    s = re.sub(r"[^\w.-]+", "_", text.strip(), flags=re.UNICODE).strip("._")
    return s or "student"


def _opt_float(raw: str | None, name: str, default: float | None) -> float | None:
    raw = (raw or "").strip()
    if not raw:
        return default
    try:
        return float(raw.replace(",", "."))
    except ValueError:
        raise TmmError(f"{name} is '{raw}', not a number") from None


def jobs_from_roster(path: str | Path, crank_rpm: float | None, torque_nm: float | None) -> tuple[list[BatchJob], list[dict]]:
    """Read a roster CSV (student,variant[,crank_rpm][,torque]); returns (jobs, bad rows).

    A bad row (missing student or variant, a value that is not a number) is returned with its
    reason; a file without the `student` and `variant` columns is an error for the whole roster.
    """
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise TmmError(f"roster {p} cannot be read ({exc.strerror or exc.__class__.__name__}); check the path") from None
    from .check import csv_delimiter

    lines = text.splitlines()
    reader = csv.DictReader(lines, delimiter=csv_delimiter(lines))
    header = [h.strip().lower() for h in (reader.fieldnames or [])]
    missing = [c for c in ("student", "variant") if c not in header]
    if missing:
        raise TmmError(f"roster {p} has no column(s) {', '.join(missing)}; the header must be student,variant[,crank_rpm][,torque]")
    jobs: list[BatchJob] = []
    bad: list[dict] = []
    used: dict[str, int] = {}
    for lineno, raw in enumerate(reader, start=2):
        row = {(k or "").strip().lower(): (v or "").strip() if isinstance(v, str) else "" for k, v in raw.items()}
        if not any(row.values()):
            continue
        student = row.get("student", "")
        label = student or f"line {lineno}"
        try:
            if not student:
                raise TmmError("the student column is empty")
            if not row.get("variant"):
                raise TmmError("the variant column is empty")
            crank = _opt_float(row.get("crank_rpm"), "crank_rpm", crank_rpm)
            torque = _opt_float(row.get("torque"), "torque", torque_nm)
        except TmmError as exc:
            bad.append(_failure_row(BatchJob(label=label, variant=row.get("variant", "")), f"roster line {lineno}: {exc}"))
            continue
        slug = _slug(student)
        used[slug] = used.get(slug, 0) + 1
        if used[slug] > 1:
            slug = f"{slug}-{used[slug]}"
        jobs.append(BatchJob(label=student, variant=row["variant"], crank_rpm=crank, torque_nm=torque, folder=slug))
    return jobs, bad


def _failure_row(job: BatchJob, reason: str) -> dict:
    row = {c: "" for c in SUMMARY_COLUMNS}
    row.update(student=job.label, variant=job.variant, status="failed", error=reason)
    return row


def summary_row(job: BatchJob, doc: dict, folder: str) -> dict:
    """One summary row from a project JSON document (the content of results.json)."""
    g, c = doc["gears"], doc["cam"]
    pl = g["planetary"]
    stages = pl["stages"]
    teeth = " + ".join(
        "/".join(str(s[k]) for k in ("z_sun", "z_planet", "z_planet2", "z_ring") if s.get(k) is not None)
        for s in stages
    )
    planets = "+".join(str(s["planets"]) for s in stages)
    pa = c["pressure_angle_max_deg"]
    row = {
        "student": job.label,
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
        "warnings": len(doc.get("warnings", [])),
        "folder": folder,
        "error": "",
    }
    return row


_FIGURE_CACHE: dict = {}  # per worker process: reducer drawings shared by rows with one crank speed


def run_job(job: BatchJob, out_dir: str, variants_file: str | None, lang: str, fmt: str, plots: bool, report: str | None,
            sheets: bool = False) -> dict:
    """Run one row in this process: the project, its folder, its summary row (or a failure row)."""
    from .project import run_project
    from .render.report import write_project_folder
    from .variants import get_variant

    try:
        v = get_variant(job.variant, variants_file)
        result = run_project(v, crank_rpm=job.crank_rpm, torque_nm=job.torque_nm)
        folder = Path(out_dir) / job.folder
        if job.folder and not job.folder.startswith("variant-"):
            folder = folder / f"variant-{v.number:02d}"
        doc, _ = write_project_folder(result, folder, lang, fmt=fmt, plots=plots, report=report, figure_cache=_FIGURE_CACHE,
                                      sheets=sheets)
        return summary_row(job, doc, str(folder))
    except TmmError as exc:
        return _failure_row(job, str(exc))
    except Exception as exc:  # a bug must not stop the class's batch; it is reported in its row
        return _failure_row(job, f"internal error {exc.__class__.__name__}: {exc}")


def _fmt_cell(value) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def write_summary_csv(path: Path, rows: list[dict]) -> None:
    """summary.csv, written to a temporary file and renamed into place."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    with open(tmp, "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=SUMMARY_COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: _fmt_cell(r.get(k)) for k in SUMMARY_COLUMNS})
    os.replace(tmp, path)


def run_batch(jobs: list[BatchJob], bad: list[dict], out_dir: Path, *, variants_file: str | None = None,
              lang: str = "en", fmt: str = "png", plots: bool = True, report: str | None = "md",
              jobs_n: int | None = None, progress: bool = False, sheets: bool = False) -> BatchSummary:
    """Run all jobs (in `jobs_n` processes), write out_dir/summary.csv, return the rows in order."""
    from .render.files import ensure_writable_dir

    out_dir = ensure_writable_dir(Path(out_dir))
    if variants_file is not None:  # fail once, early, on a broken table rather than in every row
        from .variants import load_table

        load_table(variants_file)
    n_workers = max(1, min(jobs_n or os.cpu_count() or 1, len(jobs) or 1))
    args = (str(out_dir), variants_file, lang, fmt, plots, report, sheets)
    results: dict[int, dict] = {}

    def _progress_ctx():
        if not progress:
            return None
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        return Progress(TextColumn("[bold]{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), transient=False)

    bar = _progress_ctx()
    task = None
    if bar is not None:
        bar.start()
        task = bar.add_task("tmm batch", total=len(jobs))
    try:
        if n_workers == 1:
            for i, job in enumerate(jobs):
                results[i] = run_job(job, *args)
                if bar is not None:
                    bar.advance(task)
        else:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor, as_completed

            ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else None
            with ProcessPoolExecutor(max_workers=n_workers, mp_context=ctx) as pool:
                futures = {pool.submit(run_job, job, *args): i for i, job in enumerate(jobs)}
                for fut in as_completed(futures):
                    i = futures[fut]
                    try:
                        results[i] = fut.result()
                    except Exception as exc:  # a crashed worker: report the row, go on
                        results[i] = _failure_row(jobs[i], f"worker failed: {exc.__class__.__name__}: {exc}")
                    if bar is not None:
                        bar.advance(task)
    finally:
        if bar is not None:
            bar.stop()
    rows = list(bad) + [results[i] for i in range(len(jobs))]
    write_summary_csv(out_dir / "summary.csv", rows)
    failed = tuple(r for r in rows if r["status"] != "ok")
    return BatchSummary(rows=tuple(rows), failed=failed)
