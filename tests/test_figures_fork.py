"""A forked child (tmm project's second process, a batch worker) draws with fonts of its own: no
FreeType font object made in the parent is used after the fork (they share the font file's offset,
and interleaved reads fail with "FT_Load_Glyph … invalid outline")."""

import io
import os
import sys

import pytest

from tmm_cli.render.figures import kit as figure_kit

pytestmark = pytest.mark.skipif(not hasattr(os, "fork") or not sys.platform.startswith("linux"), reason="needs fork")


def _draw(text: str) -> None:
    fig = figure_kit.new_figure(2, 1)
    fig.text(0.1, 0.5, figure_kit.mt(text), fontsize=10)
    fig.savefig(io.BytesIO(), format="png", dpi=60)


def test_the_child_parses_its_formulas_again_with_its_own_fonts():
    from matplotlib.mathtext import MathTextParser

    text = "i_пл = n_д/n_кр"
    _draw(text)  # parsed here: the cached result holds this process's FreeType fonts
    assert MathTextParser._parse_cached.cache_info().currsize > 0
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: its cache starts empty, its formula is parsed anew
        ok = 0
        try:
            fresh = MathTextParser._parse_cached.cache_info().currsize == 0
            _draw(text)
            ok = 1 if fresh else 2
        finally:
            os.write(w, bytes([ok]))
            os._exit(0)
    os.close(w)
    got = os.read(r, 1)
    os.waitpid(pid, 0)
    assert got == b"\x01", {b"\x00": "the child failed to draw", b"\x02": "the child kept the parent's formulas"}.get(got, got)
    assert MathTextParser._parse_cached.cache_info().currsize > 0  # the parent keeps its own
