"""The note for every variant: compiles, no `_`, no `--`, the variant's r0 and tooth numbers with a
decimal comma, only the textbook's equation numbers (the full run of tests/test_note.py's checks).

    python bench/note_all.py            # variants 1–68 at the default crank speed + scheme cases
    python bench/note_all.py --lang en

Figures are left out (they do not change the text); a few minutes on a laptop, most of it pypdf.
"""

from __future__ import annotations

import argparse
import re
import sys
import tempfile
import time
from pathlib import Path


def main() -> int:
    import pypdf

    from tmm_cli.project import run_project
    from tmm_cli.render.note import write_note
    from tmm_cli.i18n.numbers import num
    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.variants import load_table

    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--lang", choices=["ru", "en"], default="ru")
    args = ap.parse_args()
    book = {f"1.{i}" for i in range(1, 29)} | {f"2.{i}" for i in range(1, 6)}
    table = load_table()
    # default crank speed for every variant; crank 60 rpm gives scheme 2, 40 rpm two stages (1+1)
    cases = [(n, None) for n in sorted(table)] + [(n, c) for n in (1, 2, 3, 4, 17, 40) for c in (60.0, 40.0)]
    bad = []
    t0 = time.perf_counter()
    compile_times = []
    for number, crank in cases:
        r = run_project(table[number], crank_rpm=crank)
        with tempfile.TemporaryDirectory() as d:
            t = time.perf_counter()
            try:
                write_note(Path(d), r, args.lang, TitleFields(), {})
            except Exception as exc:  # report every failure, go on
                bad.append((number, crank, f"{exc.__class__.__name__}: {exc}"))
                continue
            compile_times.append(time.perf_counter() - t)
            text = "\n".join(p.extract_text() for p in pypdf.PdfReader(Path(d) / "note.pdf").pages)
        flat = re.sub(r"\s+", "", text)
        problems = []
        if "_" in text:
            problems.append("underscore")
        if "--" in text:
            problems.append("--")
        if num(r.cam.sizing.r0_m * 1000, args.lang, decimals=2) not in text:
            problems.append("r0 missing")
        for st in r.gears.planetary.stages:
            if "/".join(map(str, st.teeth)) not in flat:
                problems.append(f"teeth {st.teeth} missing")
        if args.lang == "ru":
            cited = set(re.findall(r"\((\d+\.\d+)\)", text))
            if cited - book:
                problems.append(f"equations not in the book: {sorted(cited - book)}")
        if problems:
            bad.append((number, crank, "; ".join(problems)))
    dt = time.perf_counter() - t0
    print(f"{len(cases)} notes ({args.lang}) in {dt:.0f} s; note build + compile: median "
          f"{sorted(compile_times)[len(compile_times) // 2]:.2f} s, worst {max(compile_times):.2f} s")
    for number, crank, why in bad:
        print(f"variant {number}" + (f" at {crank:g} rpm" if crank else "") + f": {why}")
    print("all good" if not bad else f"{len(bad)} problem(s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
