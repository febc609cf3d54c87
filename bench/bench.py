"""Benchmarks of tmm, printed as ratios to floors measured in the same run (never asserted in tests).

    python bench/bench.py              # CLI timings + in-process synthesis
    python bench/bench.py --batch      # also `tmm batch --variants 1-68 --jobs 2` (a minute or two)
    python bench/bench.py --mechanism  # only sheets 1 and 2 of the example mechanisms, in process (seconds)

Two floors: no command of ours can be faster than the libraries it needs.
- "cli floor": a fresh `python -c "import numpy, click, rich"`;
- "figure floor": a fresh python that imports matplotlib and saves one empty figure as PNG.
Each command runs right after its floor, several times, in fresh processes; the ratio printed is
the median of the per-pair ratios, so a machine shared with other jobs moves both alike. Targets
(issue 9) are printed beside the ratios. Byte-code caching is on (as after `pip install`), and one
warm-up run of each command comes first.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PY = sys.executable
TMM = [PY, "-c", "from tmm_cli.cli import main; main()"]
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
FLOORS = {
    "cli": [PY, "-c", "import numpy, click, rich"],
    "figure": [PY, "-c", "import matplotlib; matplotlib.use('agg'); from matplotlib.figure import Figure; "
                         "import tempfile, os; Figure().savefig(os.path.join(tempfile.gettempdir(), 'tmm-bench-empty.png'))"],
}


def once(cmd: list[str], check: bool = True) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=check, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV)
    return time.perf_counter() - t0


def wall(cmd: list[str], runs: int) -> float:
    """Median wall time of `cmd` over `runs` fresh runs (after one warm-up run)."""
    once(cmd)
    return statistics.median(once(cmd) for _ in range(runs))


def added(cmd: list[str], base: list[str], runs: int) -> tuple[float, float, float]:
    """What `cmd` adds to `base`: (median of the per-pair differences, median base, median cmd), the
    two run alternately so that a machine shared with other jobs slows both alike."""
    once(cmd)
    once(base)
    ds, bs, cs = [], [], []
    for _ in range(runs):
        b = once(base)
        c = once(cmd)
        ds.append(c - b)
        bs.append(b)
        cs.append(c)
    return statistics.median(ds), statistics.median(bs), statistics.median(cs)


def paired(cmd: list[str], floor: list[str], runs: int) -> tuple[float, float, float]:
    """(median time, median floor, median of the per-pair ratios) over `runs` alternating pairs."""
    once(cmd)  # warm-up: byte code, font cache
    ts, fs, rs = [], [], []
    for _ in range(runs):
        f = once(floor)
        t = once(cmd)
        ts.append(t)
        fs.append(f)
        rs.append(t / f)
    return statistics.median(ts), statistics.median(fs), statistics.median(rs)


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


def mechanism_in_process(runs: int = 20) -> list[tuple[str, float, float]]:
    """Sheet 1 of each example mechanism without figures (issue 24: 12 positions, both extreme
    positions, both plans, the dense curve): (name, median s, worst s) over `runs` analyses each,
    file reading and parsing included."""
    import tomllib

    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.sheet1 import analyse_mechanism

    out = []
    for path in sorted((Path(__file__).resolve().parents[1] / "docs" / "examples").glob("*.toml")):
        text = path.read_text(encoding="utf-8")
        try:
            data = tomllib.loads(text)
            if "crank" not in data:
                continue
        except tomllib.TOMLDecodeError:
            continue
        analyse_mechanism(parse_mechanism(data, path.name))  # warm-up
        times = []
        for _ in range(runs):
            t0 = time.perf_counter()
            analyse_mechanism(parse_mechanism(tomllib.loads(text), path.name))
            times.append(time.perf_counter() - t0)
        out.append((path.stem, statistics.median(times), max(times)))
    return out


def sheet2_in_process(runs: int = 10) -> list[tuple[str, float, float]]:
    """Sheet 2 of each example mechanism with masses, on top of its sheet 1 (issue 25: the force
    analysis of every position, Zhukovsky's lever, the 0.5° dynamics, both flywheels), no figures:
    (name, median s, worst s); sheet 1 is not counted."""
    import tomllib

    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.linkage.sheet2 import analyse_sheet2
    from tmm_cli.linkage.sheet2_file import parse_sheet2

    out = []
    for path in sorted((Path(__file__).resolve().parents[1] / "docs" / "examples").glob("*.toml")):
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except tomllib.TOMLDecodeError:
            continue
        if "crank" not in data or "mass" not in data:
            continue
        mech = parse_mechanism(data, path.name)
        s1 = analyse_mechanism(mech)
        analyse_sheet2(s1, parse_sheet2(mech))  # warm-up
        times = []
        for _ in range(runs):
            t0 = time.perf_counter()
            analyse_sheet2(s1, parse_sheet2(mech))
            times.append(time.perf_counter() - t0)
        out.append((path.stem, statistics.median(times), max(times)))
    return out


def drawings_in_process(runs: int = 5) -> list[tuple[str, str, float, float]]:
    """The A1 drawings of sheets 1 and 2 of each example mechanism, built in memory (layout, label
    placement, the ezdxf document; no DXF or PDF written): (name, sheet, median s, worst s)."""
    import tomllib

    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.linkage.sheet2 import analyse_sheet2
    from tmm_cli.linkage.sheet2_file import parse_sheet2
    from tmm_cli.render.sheets.dynamics_sheet import sheet2
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    title = TitleFields()
    out = []
    for path in sorted((Path(__file__).resolve().parents[1] / "docs" / "examples").glob("*.toml")):
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except tomllib.TOMLDecodeError:
            continue
        if "crank" not in data:
            continue
        mech = parse_mechanism(data, path.name)
        s1 = analyse_mechanism(mech)
        inp = parse_sheet2(mech)
        jobs = [("sheet 1", sheet1, s1)]
        if inp.has_forces:
            jobs.append(("sheet 2", sheet2, analyse_sheet2(s1, inp)))
        for label, build, s in jobs:
            build(s, "ru", title)  # warm-up (fonts)
            times = []
            for _ in range(runs):
                t0 = time.perf_counter()
                build(s, "ru", title)
                times.append(time.perf_counter() - t0)
            out.append((path.stem, label, statistics.median(times), max(times)))
    return out


def print_mechanisms() -> None:
    for name, median, worst in mechanism_in_process():
        print(f"sheet 1 of docs/examples/{name}.toml in process (12 positions, both plans, no figures): "
              f"median {median * 1000:.1f} ms, worst {worst * 1000:.1f} ms (target: well under 1 s)")
    for name, median, worst in sheet2_in_process():
        print(f"sheet 2 of docs/examples/{name}.toml in process (forces, lever, 0.5° dynamics, flywheels, no figures): "
              f"median {median * 1000:.1f} ms, worst {worst * 1000:.1f} ms")
    for name, label, median, worst in drawings_in_process():
        print(f"the A1 drawing of {label} of docs/examples/{name}.toml (layout, labels, DXF model; no file): "
              f"median {median * 1000:.0f} ms, worst {worst * 1000:.0f} ms (target: ≲ 300 ms)")


def note_time(variant: int = 17) -> dict:
    """The note's own work for one variant, in process (seconds): its figures drawn for the page as
    SVG (and as 300 dpi PNG for the DOCX), the document built and typeset by typst, the DOCX written.

    The screen figures are drawn by `tmm project` with any report, so they are not counted.
    """
    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.project import run_project
    from tmm_cli.render.figures.note import save_note_figure
    from tmm_cli.render.figures.note_scales import figure_size_cm
    from tmm_cli.render.note import NOTE_FIGURES, build_note, write_note
    from tmm_cli.variants import get_variant

    r = run_project(get_variant(variant))
    out = {}
    with tempfile.TemporaryDirectory() as d:
        d = Path(d)
        save_note_figure(d, r, "ru", "cam_pressure_angle")  # fonts and mathtext loaded (as before the fork)
        t0 = time.perf_counter()
        for name in NOTE_FIGURES:
            save_note_figure(d, r, "ru", name)
        out["figures (SVG)"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        for name in NOTE_FIGURES:
            save_note_figure(d, r, "ru", name, raster=True)
        out["figures (SVG + PNG 300 dpi)"] = time.perf_counter() - t0
        files = {n: (f"note_{n}.svg", f"note_{n}.png", *figure_size_cm(n, r.gears)) for n in NOTE_FIGURES}
        t0 = time.perf_counter()
        build_note(r, "ru", files)
        out["build the document"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        write_note(d, r, "ru", TitleFields(), files)
        out["build + typst (note.pdf)"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        write_note(d, r, "ru", TitleFields(), files, docx=True, pdf=False)
        out["build + note.docx"] = time.perf_counter() - t0
    return out


def sheets_in_process(variant: int = 17, runs: int = 3) -> tuple[float, float]:
    """Median seconds of write_sheets (both sheets, DXF + PDF) in this process: drawn one after the
    other, and sheet 3 in a forked child beside sheet 4 (what `tmm project` does on two cores)."""
    import tmm_cli.render.sheets as sheets
    from tmm_cli.project import run_project
    from tmm_cli.variants import load_table

    result = run_project(load_table()[variant])
    real = sheets._fork_ok
    out = []
    for fork in (False, True):
        sheets._fork_ok = (lambda: fork) if not fork else real
        times = []
        for _ in range(runs):
            with tempfile.TemporaryDirectory() as d:
                t = time.perf_counter()
                sheets.write_sheets(Path(d), result, "ru")
                times.append(time.perf_counter() - t)
        out.append(statistics.median(times))
    sheets._fork_ok = real
    return out[0], out[1]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--batch", action="store_true", help="also time tmm batch --variants 1-68 --jobs 2 (long)")
    ap.add_argument("--mechanism", action="store_true", help="only the in-process timing of sheets 1 and 2 of the example mechanisms (seconds)")
    args = ap.parse_args()
    if args.mechanism:
        print_mechanisms()
        return
    out = Path(tempfile.mkdtemp(prefix="tmm-bench-"))
    o = ["--out", str(out)]
    try:
        # (name, command, floor, target ratio or None)
        rows = [
            ("tmm --help", TMM + ["--help"], "cli", None),
            ("tmm cam --variant 17 --json --no-plots", TMM + ["cam", "--variant", "17", "--json", "--no-plots", *o], "cli", None),
            ("tmm gears --variant 17 --crank-rpm 95 --json --no-plots",
             TMM + ["gears", "--variant", "17", "--crank-rpm", "95", "--json", "--no-plots", *o], "cli", None),
            # issue 9's targets are for the project without the note and the sheets (what `project` wrote
            # then): --report md --no-sheets; the full default (note.pdf + sheets) is printed beside them
            ("tmm project --variant 17 --json --no-plots --no-sheets --report md",
             TMM + ["project", "--variant", "17", "--json", "--no-plots", "--no-sheets", "--report", "md", *o], "cli", 2.0),
            ("tmm project --variant 17 --json --no-plots (note, sheets)",
             TMM + ["project", "--variant", "17", "--json", "--no-plots", *o], "cli", None),
            ("tmm cam --variant 17 (figures)", TMM + ["cam", "--variant", "17", *o], "figure", None),
            ("tmm project --variant 17 --no-sheets --report md (figures)",
             TMM + ["project", "--variant", "17", "--no-sheets", "--report", "md", *o], "figure", 2.5),
            ("tmm project --variant 17 (figures, note.pdf, sheets)", TMM + ["project", "--variant", "17", *o], "figure", None),
            ("tmm linkage (Whitworth) --no-plots --json", TMM + ["linkage", "--r1", "0.10", "--h", "0.04", "--r2", "0.08", "--r3", "0.30",
                                                            "--b", "-0.04", "--rpm", "60", "--no-plots", "--json", *o], "cli", 2.0),
            ("tmm linkage docs/examples/shaper.toml --no-plots --json",
             TMM + ["linkage", str(Path(__file__).resolve().parents[1] / "docs" / "examples" / "shaper.toml"),
                    "--no-plots", "--json", *o], "cli", 2.0),
        ]
        print(f"{'command':66s} {'median s':>9s} {'floor s':>8s} {'ratio':>6s}  floor   target")
        for name, cmd, floor, target in rows:
            t, f, ratio = paired(cmd, FLOORS[floor], args.runs)
            goal = f"≤ {target:g}" if target else ""
            print(f"{name:66s} {t:9.3f} {f:8.3f} {ratio:6.2f}  {floor:7s} {goal}")
        # the note (issues 11, 20): what --report pdf adds to --report md, and docx to pdf, with the figures
        base = TMM + ["project", "--variant", "17", "--no-sheets", "--report", "md", *o]
        pdf = TMM + ["project", "--variant", "17", "--no-sheets", *o]
        d, b, c = added(pdf, base, args.runs)
        print(f"the note (note.pdf, its figures drawn for the page) adds to tmm project --variant 17: {d:.2f} s "
              f"({b:.2f} -> {c:.2f} s; target <= 0.5 s)")
        d, b, c = added(TMM + ["project", "--variant", "17", "--no-sheets", "--report", "pdf,docx", *o], pdf, args.runs)
        print(f"note.docx (its 300 dpi figures, the Word file) adds to that: {d:.2f} s ({b:.2f} -> {c:.2f} s; target <= 1 s)")
        for what, secs in note_time().items():
            print(f"  in one process: {what}: {secs:.2f} s")
        # the A1 sheets (issue 10): project with and without them (through the console entry point:
        # `python -m tmm_cli.cli` trips over the commands' circular import)
        tmm_main = [PY, "-c", "import sys; from tmm_cli.cli import main; sys.exit(main())"]
        with_s = wall(tmm_main + ["project", "--variant", "17", "--out", str(out)], args.runs)
        without = wall(tmm_main + ["project", "--variant", "17", "--no-sheets", "--out", str(out)], args.runs)
        print(f"sheets 3 and 4 (DXF + PDF) add to tmm project --variant 17 (figures, report): {with_s - without:.2f} s "
              f"({without:.2f} -> {with_s:.2f} s; target <= 0.3 s, issue 21)")
        seq, par = sheets_in_process()
        print(f"sheets 3 and 4 in process (variant 17): one after the other {seq:.2f} s, sheet 3 in a forked child {par:.2f} s")
        d, b, c = added(tmm_main + ["project", "--variant", "17", "--out", str(out)],
                        tmm_main + ["project", "--variant", "17", "--no-sheets", "--out", str(out)], args.runs)
        print(f"  the same, run alternately: {d:.2f} s ({b:.2f} -> {c:.2f} s)")
        print_mechanisms()
        worst, median, at = in_process_synthesis()
        print(f"in-process gear synthesis over n_cr = 30..960 rpm: worst {worst * 1000:.1f} ms (at {at:g} rpm), median {median * 1000:.1f} ms")
        if args.batch:
            f0 = once(FLOORS["figure"])
            t = once(TMM + ["batch", "--variants", "1-68", "--jobs", "2", "--out", str(out / "batch")], check=False)
            f1 = once(FLOORS["figure"])
            f = statistics.median([f0, f1, once(FLOORS["figure"])])
            print(f"tmm batch --variants 1-68 --jobs 2 (figures): {t:.1f} s, {t / 68:.2f} s per variant, "
                  f"{t / f:.0f}x the figure floor ({f:.3f} s; target ≤ 40)")
    finally:
        shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
