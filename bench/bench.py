"""Benchmarks of tmm, printed as ratios to the import floor (never asserted in tests).

    python bench/bench.py              # CLI timings + in-process synthesis
    python bench/bench.py --batch      # also `tmm batch --variants 1-68` with 1 and 2 jobs

The import floor is a fresh `python -c "import numpy, click, rich"`: no command of ours can be
faster than the libraries it needs, so ratios to it stay comparable from machine to machine.
Each figure is the median of several runs in fresh processes.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PY = sys.executable
TMM = [PY, "-m", "tmm_cli.cli"]


def wall(cmd: list[str], runs: int) -> float:
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def in_process_synthesis() -> tuple[float, float, float]:
    """Worst and median wall time of design_gears over every integer n_cr in 30..960 rpm."""
    from tmm_cli.gears.design import design_gears

    design_gears(1000, crank_rpm=100)  # warm caches / imports
    times = []
    worst_at = 0.0
    for n in range(30, 961):
        t0 = time.perf_counter()
        design_gears(1000, crank_rpm=float(n))
        dt = time.perf_counter() - t0
        if not times or dt > max(times):
            worst_at = n
        times.append(dt)
    return max(times), statistics.median(times), worst_at


def note_time(variant: int = 17) -> tuple[float, float]:
    """The note's own time for one variant, in process: (SVG copies of the figures, build + typst compile).

    The figures are drawn (and saved as PNG) by `tmm project` with any report, so they are not counted.
    """
    import io

    from tmm_cli.project import run_project
    from tmm_cli.render.cam_figures import cam_figures
    from tmm_cli.render.gears_figures import gears_figures
    from tmm_cli.render.note import NOTE_FIGURES, write_note
    from tmm_cli.titleblock import TitleFields
    from tmm_cli.variants import get_variant

    r = run_project(get_variant(variant))
    figs = {**gears_figures(r.gears, "ru"), **cam_figures(r.cam, "ru")}
    with tempfile.TemporaryDirectory() as d:
        for f in figs.values():
            f.savefig(io.BytesIO(), format="png", dpi=120)
        t0 = time.perf_counter()
        for name in NOTE_FIGURES:
            figs[name].savefig(Path(d) / f"{name}.svg", format="svg")
        t1 = time.perf_counter()
        write_note(Path(d), r, "ru", TitleFields(), {n: f"{n}.svg" for n in NOTE_FIGURES})
        t2 = time.perf_counter()
    return t1 - t0, t2 - t1


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--batch", action="store_true", help="also time tmm batch --variants 1-68 (about a minute)")
    args = ap.parse_args()
    out = Path(tempfile.mkdtemp(prefix="tmm-bench-"))
    try:
        floor = wall([PY, "-c", "import numpy, click, rich"], args.runs)
        print(f"import floor (numpy, click, rich): {floor:.3f} s")
        rows = [
            ("tmm --help", TMM + ["--help"]),
            ("tmm cam --variant 17 --json --no-plots", TMM + ["cam", "--variant", "17", "--json", "--no-plots", "--out", str(out)]),
            ("tmm cam --variant 17 (figures)", TMM + ["cam", "--variant", "17", "--out", str(out)]),
            ("tmm gears --variant 17 --crank-rpm 95 --json --no-plots", TMM + ["gears", "--variant", "17", "--crank-rpm", "95", "--json", "--no-plots", "--out", str(out)]),
            ("tmm project --variant 17 (figures, note.pdf)", TMM + ["project", "--variant", "17", "--out", str(out)]),
            ("tmm project --variant 17 --report md (figures)", TMM + ["project", "--variant", "17", "--report", "md", "--out", str(out)]),
            ("tmm linkage (Whitworth, seed 003) --no-plots --json", [PY, "-c", "from tmm_cli.cli import main; main()", "linkage", "--r1", "0.10", "--h", "0.04", "--r2", "0.08", "--r3", "0.30", "--b", "-0.04", "--rpm", "60", "--no-plots", "--json", "--out", str(out)]),
        ]
        print(f"{'command':58s} {'median s':>9s} {'x floor':>8s}")
        for name, cmd in rows:
            t = wall(cmd, args.runs)
            print(f"{name:58s} {t:9.3f} {t / floor:8.2f}")
        svg, note = note_time()
        print(f"the note for variant 17 in process: SVG copies {svg:.2f} s + build and typst compile {note:.2f} s "
              f"= {svg + note:.2f} s (target 2 s)")
        # the A1 sheets (issue 10): project with and without them (through the console entry point:
        # `python -m tmm_cli.cli` trips over the commands' circular import)
        tmm_main = [PY, "-c", "import sys; from tmm_cli.cli import main; sys.exit(main())"]
        with_s = wall(tmm_main + ["project", "--variant", "17", "--out", str(out)], args.runs)
        without = wall(tmm_main + ["project", "--variant", "17", "--no-sheets", "--out", str(out)], args.runs)
        print(f"sheets 3 and 4 (DXF + PDF) add to tmm project --variant 17 (figures, report): {with_s - without:.2f} s "
              f"({without:.2f} -> {with_s:.2f} s; target <= 3 s)")
        worst, median, at = in_process_synthesis()
        print(f"in-process gear synthesis over n_cr = 30..960 rpm: worst {worst * 1000:.1f} ms (at {at:g} rpm), median {median * 1000:.1f} ms")
        if args.batch:
            for jobs in (1, 2):
                t0 = time.perf_counter()
                subprocess.run(TMM + ["batch", "--variants", "1-68", "--jobs", str(jobs), "--out", str(out / f"b{jobs}")],
                               check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                t = time.perf_counter() - t0
                print(f"tmm batch --variants 1-68 --jobs {jobs} (figures): {t:.1f} s, {t / 68:.2f} s per variant, {t / floor:.0f}x floor")
    finally:
        shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
