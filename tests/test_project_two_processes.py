"""One project's work spread over two processes (render/figures/kit.SharedWork, render/project.write_project_folder):
the same files as one process writes, a failed or killed child's work redone here, no orphan
process and no staging folder after Ctrl-C, nothing drawn that is not written, and a batch
worker's cache of the drawings several variants share. Nothing here is timed (bench/bench.py)."""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tmm_cli.project import run_project
from tmm_cli.render import project as report
from tmm_cli.render.figures import kit as figure_kit
from tmm_cli.render.figures import pipeline
from tmm_cli.variants import get_variant

fork_only = pytest.mark.skipif(not figure_kit.can_fork(), reason="fork on Linux with two cores")
TMM = [sys.executable, "-c", "from tmm_cli.cli import main; main()"]


def _gone(pid) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


def _writer(folder: Path, name: str, fail_in_child: bool = False, parent: int = os.getpid()):
    def task():
        if fail_in_child and os.getpid() != parent:
            (folder / name).write_text("half")
            raise RuntimeError("the child fails")
        (folder / name).write_text(f"{name} by {'child' if os.getpid() != parent else 'parent'}")
    return task


@fork_only
def test_shared_work_runs_every_task_once_in_either_process(tmp_path):
    names = [f"f{i}" for i in range(6)]
    with figure_kit.SharedWork([_writer(tmp_path, n) for n in names], [_writer(tmp_path, "sheets")]) as work:
        assert work.pid is not None
        work.wait_shared()
        assert all((tmp_path / n).exists() for n in names)
    assert work.pid is None  # reaped
    assert (tmp_path / "sheets").read_text() == "sheets by child"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(names + ["sheets"])


@fork_only
def test_a_failed_child_task_is_redone_here_whole(tmp_path):
    work = figure_kit.SharedWork([_writer(tmp_path, "a"), _writer(tmp_path, "b")],
                                 [_writer(tmp_path, "sheets", fail_in_child=True)])
    work.wait()
    assert [(tmp_path / n).read_text() for n in ("a", "b", "sheets")] == ["a by parent", "b by parent", "sheets by parent"]


def test_without_fork_the_tasks_run_here_in_order(tmp_path):
    work = figure_kit.SharedWork([_writer(tmp_path, "a"), _writer(tmp_path, "b")], [_writer(tmp_path, "c")], fork=False)
    assert work.pid is None and not (tmp_path / "a").exists()
    work.wait_shared()
    assert (tmp_path / "b").read_text() == "b by parent" and not (tmp_path / "c").exists()
    work.wait()
    assert (tmp_path / "c").read_text() == "c by parent"


@fork_only
def test_an_error_here_kills_and_reaps_the_child(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with figure_kit.SharedWork([], [lambda: time.sleep(60)]) as work:
            pid = work.pid
            raise KeyboardInterrupt
    assert work.pid is None and _gone(pid)


@fork_only
def test_a_signal_while_waiting_for_the_child_kills_and_reaps_it(tmp_path):
    """The body ends normally and the wait for the child (the sheets) is cut by Ctrl-C: the child
    must not go on writing into a staging folder the caller is removing (a leftover
    ``.variant-17.tmp-…`` under load)."""
    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(KeyboardInterrupt):
            with figure_kit.SharedWork([], [lambda: time.sleep(60)]) as work:
                pid = work.pid
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    assert work.pid is None and _gone(pid)


@pytest.fixture(scope="module")
def project17():
    return run_project(get_variant("17", None))


def _names(folder: Path):
    return sorted(p.name for p in folder.iterdir())


@fork_only
@pytest.mark.parametrize("report_kind", ["md", "pdf"])
def test_two_processes_write_what_one_writes(project17, tmp_path, monkeypatch, report_kind):
    from tmm_cli.render.project import write_project_folder

    _, two = write_project_folder(project17, tmp_path / "two", "ru", report=report_kind, sheets=True)
    monkeypatch.setattr(figure_kit, "can_fork", lambda: False)
    _, one = write_project_folder(project17, tmp_path / "one", "ru", report=report_kind, sheets=True)
    assert two == one == _names(tmp_path / "two")[1:]  # [0] is the manifest .tmm-files.json
    pngs = [n for n in one if n.endswith(".png")]
    assert len(pngs) == 8 and {"sheet3.pdf", "sheet4.dxf"} <= set(one)
    svgs = [n for n in one if n.endswith(".svg")]
    assert len(svgs) == (7 if report_kind == "pdf" else 0)  # the note's copies, only for the note
    if report_kind == "md":
        md = (tmp_path / "two" / "report.md").read_text(encoding="utf-8")
        assert all(f"({n})" in md for n in pngs if n != "cam_profile_scaled.png")
    # the same drawings: the PNGs agree pixel for pixel
    from PIL import Image, ImageChops

    for n in pngs:
        a, b = Image.open(tmp_path / "one" / n), Image.open(tmp_path / "two" / n)
        assert a.size == b.size and ImageChops.difference(a.convert("RGB"), b.convert("RGB")).getbbox() is None, n


@fork_only
@pytest.mark.parametrize("command, n", [("cam", 5), ("gears", 3)])
def test_cam_and_gears_draw_over_two_processes_what_one_draws(tmp_path, monkeypatch, command, n):
    from click.testing import CliRunner
    from PIL import Image, ImageChops

    from tmm_cli.cli import cli

    args = [command, "--variant", "17", "--lang", "ru"]
    assert CliRunner().invoke(cli, [*args, "--out", str(tmp_path / "two")]).exit_code == 0
    monkeypatch.setattr(figure_kit, "can_fork", lambda: False)
    assert CliRunner().invoke(cli, [*args, "--out", str(tmp_path / "one")]).exit_code == 0
    one, two = tmp_path / "one" / "variant-17", tmp_path / "two" / "variant-17"
    assert _names(one) == _names(two)
    pngs = [p.name for p in one.glob("*.png")]
    assert len(pngs) == n
    for name in pngs:
        a, b = Image.open(one / name).convert("RGB"), Image.open(two / name).convert("RGB")
        assert a.size == b.size and ImageChops.difference(a, b).getbbox() is None, name


@fork_only
def test_a_child_that_fails_drawing_is_replaced_here(project17, tmp_path, monkeypatch):
    parent = os.getpid()
    original = pipeline._draw_and_save

    def flaky(tmp, result, lang, fmt, names, svg):
        if os.getpid() != parent:  # the child draws one figure, and dies half-way
            (Path(tmp) / f"{names[0]}.{fmt}").write_bytes(b"half")  # a half-written file, then a crash
            os._exit(3)
        return original(tmp, result, lang, fmt, names, svg)

    monkeypatch.setattr(pipeline, "_draw_and_save", flaky)
    _, written = report.write_project_folder(project17, tmp_path, "en", report="md", sheets=False)
    pngs = [n for n in written if n.endswith(".png")]
    assert len(pngs) == 8 and not [n for n in _names(tmp_path) if n.startswith(".") and n != ".tmm-files.json"]
    for n in pngs:
        assert (tmp_path / n).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", n


def test_no_plots_draws_nothing(project17, tmp_path, monkeypatch):
    def never(*a, **k):
        raise AssertionError("a figure was drawn under --no-plots")

    monkeypatch.setattr(pipeline, "_draw_and_save", never)
    monkeypatch.setattr(figure_kit, "_warm_up", never)
    _, written = report.write_project_folder(project17, tmp_path / "a", "ru", plots=False, report="md", sheets=False)
    assert written == ["cam_profile.csv", "report.md", "results.json"]
    _, written = report.write_project_folder(project17, tmp_path / "b", "ru", plots=False, report="md", sheets=False,
                                             figure_cache={})
    assert written == ["cam_profile.csv", "report.md", "results.json"]


def test_json_no_plots_without_note_and_sheets_imports_no_matplotlib(tmp_path):
    code = (
        "import sys\n"
        "from tmm_cli.cli import main\n"
        "try:\n"
        f"    main(['project', '--variant', '17', '--json', '--no-plots', '--no-sheets', '--report', 'md',"
        f" '--out', {str(tmp_path)!r}])\n"
        "except SystemExit:\n"
        "    pass\n"
        "sys.stderr.write(repr(sorted(m for m in ('rich.table', 'matplotlib', 'ezdxf', 'typst') if m in sys.modules)))\n"
    )
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert json.loads(res.stdout)["variant"] == 17
    assert res.stderr.strip() == "[]"


def test_batch_cache_draws_a_shared_spur_mesh_once(tmp_path, monkeypatch):
    """Variants 3 and 21 have one spur pair (and one reducer at the default crank speed)."""
    from tmm_cli.render.figures import gears as gf

    drawn = []
    original = gf.gears_figures

    def spy(result, lang, names=None):
        drawn.extend(names or ("gears_planetary", "gears_assembly", "gears_mesh"))
        return original(result, lang, names=names)

    monkeypatch.setattr(gf, "gears_figures", spy)
    cache = {}
    a, b = run_project(get_variant("3", None)), run_project(get_variant("21", None))
    assert repr(a.gears.spur) == repr(b.gears.spur)
    report.write_project_folder(a, tmp_path / "a", "ru", report="pdf", figure_cache=cache)
    report.write_project_folder(b, tmp_path / "b", "ru", report="pdf", figure_cache=cache)
    assert sorted(drawn) == ["gears_assembly", "gears_mesh", "gears_planetary"]
    for n in ("gears_mesh.png", "note_gears_mesh.svg", "gears_planetary.png"):
        assert (tmp_path / "a" / n).read_bytes() == (tmp_path / "b" / n).read_bytes()
    assert (tmp_path / "b" / "note.pdf").is_file()
    # a different spur pair is drawn anew, the reducer still comes from the cache
    report.write_project_folder(run_project(get_variant("4", None)), tmp_path / "c", "ru", report="pdf", figure_cache=cache)
    assert sorted(drawn) == ["gears_assembly", "gears_mesh", "gears_mesh", "gears_planetary"]


@fork_only
@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize("sig, code, to_group", [(signal.SIGINT, 130, True), (signal.SIGTERM, 143, False)])
def test_interrupted_project_leaves_no_staging_and_no_child(tmp_path, sig, code, to_group):
    """A run that ended before the signal could be sent is started again (at most 3 times, then the
    test fails: it tested nothing); a run alive when the signal went must exit with `code` — an
    exit 0 then is a run that ignored the signal."""
    env = dict(os.environ, MPLBACKEND="Agg", LANG="en_US.UTF-8", LC_ALL="")
    for attempt in range(3):
        out = tmp_path / f"o{attempt}"
        p = subprocess.Popen(TMM + ["project", "--variant", "17", "--out", str(out)], cwd=tmp_path,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True, env=env)
        end = time.monotonic() + 120
        while time.monotonic() < end and p.poll() is None and not list(out.glob(".*tmp-*/*.png")):
            time.sleep(0.02)  # until the figures are being written (the child is at work)
        if p.poll() is None:
            (os.killpg if to_group else os.kill)(p.pid, sig)
            break
        p.communicate(timeout=60)
    else:
        pytest.fail("the run finished before the signal could be sent, 3 times")
    _, err = p.communicate(timeout=60)
    assert p.returncode == code, (p.returncode, err)
    assert err.decode().strip().splitlines() == ["tmm: interrupted"]
    end = time.monotonic() + 5
    while time.monotonic() < end:
        try:
            os.killpg(p.pid, 0)
        except ProcessLookupError:
            break
        time.sleep(0.05)
    else:
        pytest.fail("the child process outlived tmm project")
    assert [q for q in tmp_path.rglob("*") if ".tmp-" in q.name] == []
    assert not (out / "variant-17").exists()


def test_batch_forks_its_workers_before_any_thread_starts(tmp_path):
    """The progress bar's refresh thread ran when the pool forked its workers (Python 3.12+ warns:
    a child can inherit a lock that thread held). Every fork of a batch sees one thread."""
    probe = ("import os, sys, threading\n"
             "real = os.fork\n"
             "def fork():\n"
             "    print('threads at fork:', threading.active_count(), file=sys.stderr, flush=True)\n"
             "    return real()\n"
             "os.fork = fork\n"
             "from tmm_cli.cli import main; main()\n")
    res = subprocess.run([sys.executable, "-c", probe, "batch", "--variants", "1-3", "--jobs", "2", "--no-plots",
                          "--report", "none", "--out", str(tmp_path / "o")], capture_output=True, text=True,
                         env=dict(os.environ, MPLBACKEND="Agg"), timeout=300)
    assert res.returncode == 0, res.stderr
    counts = [line.split(":")[1].strip() for line in res.stderr.splitlines() if line.startswith("threads at fork:")]
    assert counts and set(counts) == {"1"}, res.stderr
