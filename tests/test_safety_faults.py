"""Issue 19, fault injection into `tmm batch`: a worker killed, the parent killed, Ctrl-C and SIGHUP.

Each test runs a real batch in its own session, with the rows slowed down (a wrapper around
`run_job`, inherited by the forked workers) and every row's start marked by the worker that took
it, so the fault lands at a known moment. Each asserts which rows completed, that no process of the
batch survives, and that no temporary folder remains (in --out nor in the temporary space, which
is the test's own).
"""

import csv
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from cli_helpers import group_gone, wait_for

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="POSIX signals, fork")

# the batch with each row delayed; a row's start is marked by a file start-VARIANT-PID
SLOW = """
import os, sys, time
import tmm_cli.teacher.batch as batch
real = batch.run_job
def slow(job, *args):
    open(os.path.join(os.environ["MARKS"], "start-%s-%d" % (job.variant, os.getpid())), "w").close()
    time.sleep(float(os.environ["DELAY"]))
    return real(job, *args)
batch.run_job = slow
from tmm_cli.cli import main
main()
"""


def _start(tmp_path, args, delay=0.6):
    marks = tmp_path / "marks"
    marks.mkdir(exist_ok=True)
    tmp = tmp_path / "tmpdir"
    tmp.mkdir(exist_ok=True)
    env = dict(os.environ, MPLBACKEND="Agg", LANG="en_US.UTF-8", LC_ALL="", MARKS=str(marks), DELAY=str(delay),
               TMPDIR=str(tmp))
    p = subprocess.Popen([sys.executable, "-c", SLOW, "--lang", "en", "batch", *map(str, args)], cwd=tmp_path,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True, env=env)
    return p, marks, tmp


def _started(marks: Path) -> dict[str, int]:
    """{variant: pid of the worker that took it}"""
    out = {}
    for f in marks.iterdir():
        _, variant, pid = f.name.split("-")
        out[variant] = int(pid)
    return out




def _no_temporaries(out: Path, tmp: Path):
    assert [q for q in out.rglob("*") if ".tmp-" in q.name] == []
    assert list(tmp.iterdir()) == [], list(tmp.iterdir())  # no /tmp/tmm-figures-*


def _rows(out: Path) -> dict[str, dict]:
    return {r["variant"]: r for r in csv.DictReader((out / "summary.csv").open(encoding="utf-8"))}


def test_one_killed_worker_fails_its_row_only(tmp_path):
    """kill -9 of a worker in the middle of variant 3: variant 3 fails with the signal, the other
    rows all complete (concurrent.futures failed every pending row: 38 of 40)."""
    out = tmp_path / "o"
    p, marks, tmp = _start(tmp_path, ["--variants", "1-6", "--jobs", 2, "--out", out, "--no-plots", "--report", "none"],
                           delay=0.4)
    assert wait_for(lambda: "3" in _started(marks) or p.poll() is not None)
    os.kill(_started(marks)["3"], signal.SIGKILL)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 1, err  # a failed row
    rows = _rows(out)
    assert rows["3"]["status"] == "failed" and "SIGKILL" in rows["3"]["error"], rows["3"]
    assert all(rows[str(v)]["status"] == "ok" for v in (1, 2, 4, 5, 6)), rows
    assert {q.name for q in out.iterdir() if q.is_dir()} == {f"variant-{v:02d}" for v in (1, 2, 4, 5, 6)}
    assert wait_for(lambda: group_gone(p.pid), 5), "a worker outlived the batch"
    _no_temporaries(out, tmp)


def test_killing_the_parent_kills_its_workers_and_frees_the_folder(tmp_path):
    """kill -9 of the batch: its workers die with it (they held the --out lock forever), the shared
    drawings' temporary folder goes, and the next batch takes the stale lock over, saying so."""
    out = tmp_path / "o"
    p, marks, tmp = _start(tmp_path, ["--variants", "1-4", "--jobs", 2, "--out", out, "--report", "none"], delay=3)
    assert wait_for(lambda: len(_started(marks)) >= 2 or p.poll() is not None)
    workers = set(_started(marks).values())
    os.kill(p.pid, signal.SIGKILL)
    p.communicate(timeout=30)
    assert wait_for(lambda: group_gone(p.pid), 5), "a worker outlived its killed batch"
    for pid in workers:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)
    _no_temporaries(out, tmp)
    assert (out / ".tmm-batch.lock").read_text().split()[0] == str(p.pid)  # left by the kill: stale
    res = subprocess.run([sys.executable, "-m", "tmm_cli", "--lang", "en", "batch", "--variants", "5", "--out", str(out),
                          "--no-plots", "--report", "none"], capture_output=True, text=True, cwd=tmp_path,
                         env=dict(os.environ, MPLBACKEND="Agg"))
    assert res.returncode == 0, res.stderr
    assert f"took over the lock of {out}" in " ".join(res.stdout.split()) and str(p.pid) in res.stdout
    assert not (out / ".tmm-batch.lock").exists()
    assert set(_rows(out)) == {"5"} and {q.name for q in out.iterdir() if q.is_dir()} == {"variant-05"}


@pytest.mark.parametrize("sig, code, plots", [(signal.SIGINT, 130, "--no-plots"), (signal.SIGHUP, 129, "--format=png")])
def test_ctrl_c_or_hangup_stop_the_batch_and_leave_nothing(tmp_path, sig, code, plots):
    """Ctrl-C, or the terminal closing (SIGHUP to the whole group): the rows done are in the
    summary, the rest marked not run; no process, no staging folder, no /tmp/tmm-figures-* (the
    drawings the workers share, made when there are figures)."""
    out = tmp_path / "o"
    p, marks, tmp = _start(tmp_path, ["--variants", "1-6", "--jobs", 2, "--out", out, "--report", "none", plots],
                           delay=0.3)
    assert wait_for(lambda: len(list(out.glob("variant-*/results.json"))) >= 2 and len(_started(marks)) >= 4
                     or p.poll() is not None, 120)
    assert p.poll() is None, p.communicate()
    os.killpg(p.pid, sig)
    _, err = p.communicate(timeout=60)
    assert p.returncode == code, err
    assert err.decode().strip().startswith("tmm: interrupted:"), err
    assert wait_for(lambda: group_gone(p.pid), 5)
    rows = _rows(out)
    done = {v for v, r in rows.items() if r["status"] == "ok"}
    assert done and any(r["status"].startswith("not run") for r in rows.values())  # a row whose result was on its
    # way when the signal came is not run, and its folder goes: the summary describes exactly the folders
    assert {q.name for q in out.iterdir() if q.is_dir()} == {f"variant-{int(v):02d}" for v in done}
    _no_temporaries(out, tmp)


def test_workers_are_spawned_where_fork_is_not_the_platform_s_way(tmp_path):
    """macOS and Windows spawn their workers: the task and initializer must reach a fresh
    interpreter (here forced on Linux), and the rows come out the same."""
    from tmm_cli.teacher.batch import run_batch
    from tmm_cli.teacher.roster import jobs_from_spec
    from tmm_cli.teacher.workers import start_method

    assert start_method() == "fork"  # Linux
    jobs = jobs_from_spec("3-5", None, None)
    spawned = run_batch(jobs, [], tmp_path / "s", plots=False, report=None, jobs_n=2, start_method="spawn")
    forked = run_batch(jobs, [], tmp_path / "f", plots=False, report=None, jobs_n=2, start_method="fork")
    assert [r["status"] for r in spawned.rows] == ["ok"] * 3
    strip = lambda rows: [{k: v for k, v in r.items() if k != "folder"} for r in rows]  # noqa: E731
    assert strip(spawned.rows) == strip(forked.rows)


def test_a_live_lock_is_refused_and_a_stale_one_taken_over(tmp_path):
    from tmm_cli.errors import TmmError
    from tmm_cli.output.lock import LOCK_FILE, batch_lock

    said = []
    with batch_lock(tmp_path, say=said.append):
        assert (tmp_path / LOCK_FILE).read_text().strip() == str(os.getpid())
        child = subprocess.run([sys.executable, "-c", "from tmm_cli.output.lock import batch_lock\n"
                                f"with batch_lock({str(tmp_path)!r}): pass"], capture_output=True, text=True)
        assert child.returncode == 1 and "another tmm batch is writing into" in child.stderr
    assert not (tmp_path / LOCK_FILE).exists() and said == []
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    (tmp_path / LOCK_FILE).write_text(f"{dead.pid}\n")
    with batch_lock(tmp_path, say=said.append):
        pass
    assert said == [dead.pid]
    (tmp_path / LOCK_FILE).symlink_to(tmp_path / "elsewhere")
    with pytest.raises(TmmError, match="cannot lock"):
        with batch_lock(tmp_path):
            pass
    assert not (tmp_path / "elsewhere").exists()
