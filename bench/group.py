"""The teacher's semester, timed: a group of 68 students (every variant once, crank speeds and
moments of their own) through `tmm assign`, `tmm batch --sheets --report pdf --jobs 2` (notes and
drawing sheets) and `tmm check` with feedback (issue 22: the batch in at most 60 s on 2 cores).

    python bench/group.py            # the whole semester (about two minutes)
    python bench/group.py --batch    # the batch only

Each command runs once, in a fresh process, as a teacher runs it. Printed: the wall time, the
processor time of the command and every process it started (user + system, from the operating
system's accounting of the finished children), and that processor time divided by 2 — the wall
time the command would take on two cores that nothing else uses. The load average before and
after says how busy the machine was; on a machine shared with other work the wall time is
longer than the last column, never shorter.
"""

from __future__ import annotations

import argparse
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PY = sys.executable
TMM = [PY, "-c", "from tmm_cli.cli import main; main()"]
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
N = 68


def roster(path: Path) -> None:
    """68 students, variants 1–68 shuffled (seed 22), crank speeds 60–140 rpm, some moments."""
    rng = random.Random(22)
    variants = list(range(1, N + 1))
    rng.shuffle(variants)
    lines = ["student;group;variant;n_кр;момент"]
    for i, v in enumerate(variants, start=1):
        crank = rng.choice((60, 67, 80, 95, 110, 120, 140))
        torque = "" if i % 3 else f"{rng.randint(50, 200)}"
        lines.append(f"Студент {i:02d};П-2{40 + i % 3};{v};{crank};{torque}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def answers(folder: Path, out: Path) -> None:
    """Each student's answers: the batch's own numbers, one student in four off in r0 by 10 %."""
    import json

    folder.mkdir(exist_ok=True)
    for i, res in enumerate(sorted(out.glob("Студент_*/variant-*/results.json"))):
        doc = json.loads(res.read_text(encoding="utf-8"))
        g, c = doc["gears"], doc["cam"]
        st = g["planetary"]["stages"][0]
        a = {"n_motor_rpm": g["motor"]["n_rpm"], "z_sun": st["z_sun"], "z_planet": st["z_planet"], "z_ring": st["z_ring"],
             "planets": st["planets"], "z1": g["spur"]["z1"], "z2": g["spur"]["z2"], "eps_alpha": round(g["spur"]["eps_alpha"], 3),
             "r0_mm": round(c["r0_mm"] * (0.9 if i % 4 == 0 else 1.0), 2)}
        if st.get("z_planet2"):
            a["z_planet2"] = st["z_planet2"]
        if c.get("e_mm") is not None:
            a["e_mm"] = round(c["e_mm"], 2)
        if c.get("l_oc_mm") is not None:
            a["l_oc_mm"] = round(c["l_oc_mm"], 2)
        (folder / f"{res.parent.parent.name}.toml").write_text("".join(f"{k} = {v}\n" for k, v in a.items()), encoding="utf-8")


def timed(label: str, args: list[str]) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    load0 = os.getloadavg()[0]
    t0 = time.perf_counter()
    proc = subprocess.run(TMM + args, env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    load1 = os.getloadavg()[0]
    status = "" if proc.returncode in (0, 1) else f"  (exit {proc.returncode}: {proc.stderr.strip()[:200]})"
    print(f"{label:<44} wall {wall:6.1f} s   cpu {cpu:6.1f} s   cpu/2 {cpu / 2:6.1f} s   "
          f"{cpu / N:5.2f} cpu-s a student   load {load0:.1f} → {load1:.1f}{status}")
    return wall


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--batch", action="store_true", help="time the batch only")
    args = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="tmm-bench-group-"))
    try:
        roster(tmp / "roster.csv")
        out = tmp / "out"
        print(f"{N} students, {os.cpu_count()} cores on this machine")
        if not args.batch:
            timed("tmm assign (68 PDFs and the merged one)", ["assign", "--roster", str(tmp / "roster.csv"), "--out",
                                                                str(tmp / "assign"), "--lang", "ru"])
        timed("tmm batch --sheets --report pdf --jobs 2", ["batch", "--roster", str(tmp / "roster.csv"), "--out", str(out),
                                                            "--sheets", "--report", "pdf", "--jobs", "2", "--lang", "ru"])
        if not args.batch:
            answers(tmp / "answers", out)
            timed("tmm check (feedback as Markdown and PDF)", ["check", "--roster", str(tmp / "roster.csv"), "--answers-dir",
                                                               str(tmp / "answers"), "--out", str(out), "--feedback", "pdf",
                                                               "--lang", "ru"])
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
