"""What each of the matplotlib hooks of tmm_cli/render/figures/agg.py saves (never asserted in tests).

    python bench/figure_hooks.py            # all hooks, none, and all but one, for each hook
    python bench/figure_hooks.py --rounds 5

Each configuration runs in a fresh process (``TMM_MPL_HOOKS`` chooses the hooks) that computes
variants 17, 3, 40 and 65, then draws and saves (PNG, 120 dpi, in memory) the eight figures of each
and the SVG copies the note takes:
the first variant is what one `tmm project` draws (cold: fonts, grammar, caches empty), the other
three what a batch worker draws next (warm). Times are CPU seconds of the drawing process
(``time.process_time``), so other jobs on the machine move them less than wall time; the
configurations take turns, round after round, and the medians are printed.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

VARIANTS = (17, 3, 40, 65)


def child() -> None:
    import io

    from tmm_cli.project import run_project
    from tmm_cli.render.figures import agg
    from tmm_cli.render.figures.cam import cam_figures
    from tmm_cli.render.figures.gears import gears_figures
    from tmm_cli.render.figures.kit import _warm_up
    from tmm_cli.variants import get_variant

    from tmm_cli.render.figures.kit import share_svg_text
    from tmm_cli.render.note import NOTE_FIGURES

    results = [run_project(get_variant(n)) for n in VARIANTS]
    import matplotlib  # noqa: F401  (imported before the clock starts: the floor's share)
    import matplotlib.backends.backend_svg  # noqa: F401

    times = []
    t0 = time.process_time()
    _warm_up()
    share_svg_text()
    for r in results:
        figs = {**gears_figures(r.gears, "ru"), **cam_figures(r.cam, "ru")}
        for fig in figs.values():
            fig.savefig(io.BytesIO(), format="png", dpi=120)
        for name in NOTE_FIGURES:  # the note's SVG copies, as tmm project makes them
            figs[name].savefig(io.BytesIO(), format="svg")
        t1 = time.process_time()
        times.append(t1 - t0)
        t0 = t1
    print(json.dumps({"hooks": sorted(agg.hooks()), "cold": times[0], "warm": sum(times[1:]) / len(times[1:])}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child()
        return
    from tmm_cli.render.figures import agg

    every = sorted(agg.available())
    configs = {"all": ",".join(every), "none": "off"}
    configs.update({f"all but {h}": ",".join(x for x in every if x != h) or "off" for h in every})
    got: dict = {name: [] for name in configs}
    for _ in range(args.rounds):
        for name, hooks in configs.items():
            env = {**os.environ, "TMM_MPL_HOOKS": hooks, "MPLBACKEND": "Agg"}
            out = subprocess.run([sys.executable, __file__, "--child"], env=env, check=True, capture_output=True, text=True)
            got[name].append(json.loads(out.stdout))
    import matplotlib

    base = {k: statistics.median(r[k] for r in got["all"]) for k in ("cold", "warm")}
    print(f"matplotlib {matplotlib.__version__}; CPU s, median of {args.rounds}: one project's eight figures "
          f"(cold), then one more variant's in the same process (warm)")
    print(f"{'hooks':28s} {'cold s':>7s} {'vs all':>7s} {'warm s':>7s} {'vs all':>7s}")
    for name in configs:
        m = {k: statistics.median(r[k] for r in got[name]) for k in ("cold", "warm")}
        print(f"{name:28s} {m['cold']:7.3f} {m['cold'] / base['cold'] - 1:+7.1%} {m['warm']:7.3f} {m['warm'] / base['warm'] - 1:+7.1%}")


if __name__ == "__main__":
    main()
