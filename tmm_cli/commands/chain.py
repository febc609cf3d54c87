"""`tmm chain FILE.toml`: the closing link of a dimensional chain by the worst-case and the
probabilistic methods (seed 003, second article; docs/accuracy.md).

Only click is imported at module level (``tmm --help`` stays instant); the core and the renderers
are imported inside the command.
"""

from __future__ import annotations

from pathlib import Path

import click

from .emit import emit
from .options import CONTEXT, force_option, json_option, lang_option, resolve_lang


def _json_name(stem: str) -> str:
    """The JSON file's name after the chain file's: letters, digits, '.', '-', '_' (64 at most).

    >>> _json_name("chain-radial-1"), _json_name("../цепь (1)"), _json_name("...")
    ('chain-radial-1.json', 'цепь_1.json', 'chain.json')
    """
    import re

    text = re.sub(r"[^\w.-]+", "_", stem).strip("._-")[:64].rstrip("._-")
    return (text or "chain") + ".json"


@click.command("chain", context_settings=CONTEXT)
@click.argument("chain_file", type=click.Path(dir_okay=False), metavar="FILE.toml")
@click.option("--risk", "risk_pct", type=float, default=0.27, show_default=True, metavar="PCT",
              help="Risk that the closing link falls outside its probabilistic limits [%] (0.27: t = 3).")
@json_option
@force_option
@click.option("--out", type=click.Path(file_okay=False), default=None, metavar="DIR",
              help="Output folder (default ./tmm-out); files go to DIR/chain/.")
@lang_option
def chain_cmd(chain_file, risk_pct, as_json, force, out, lang):
    """Dimensional chain: the closing link by the maximum–minimum and the probabilistic methods.

    FILE.toml holds the chain's name, units and [[link]] tables (name, nominal, es, ei, sign; optional
    distribution, asymmetry; in an angular chain a hub's clearance and length, β = arctg(δ/l)), as in
    A. I. Abdullaev, G. N. Rasulov, dimensional chains of package reducers (docs/accuracy.md). Example:

    \b
        tmm chain docs/examples/chain-radial-1.toml
    """
    from ..accuracy.chain import solve_chain
    from ..accuracy.chain_input import parse_chain
    from ..inputs.tables import read_text
    from ..limits import CHAIN_BYTES

    lang = resolve_lang(lang)
    text = read_text(chain_file, str(chain_file), CHAIN_BYTES).text
    result = solve_chain(one_line_names(parse_chain(text, str(chain_file))), risk_pct)

    from ..output.folder import ensure_writable_dir
    from ..render.data.chain import chain_document

    folder = (Path(out) if out else Path("tmm-out")) / "chain"
    ensure_writable_dir(folder.parent)
    doc = chain_document(result, lang)
    name = _json_name(Path(chain_file).stem)

    def show(console):
        from ..render.terminal.chain import print_chain

        print_chain(console, result, lang)

    emit(folder, {name: doc}, None, "png", doc if as_json else None, show, result.notes, lang, owns=(name,), writer="chain", force=force)


def one_line_names(chain):
    """The chain's and its links' names as one line each (a person's text: inputs/names.clean_text)."""
    from dataclasses import replace

    from ..inputs.names import clean_text

    return replace(chain, name=clean_text(chain.name, 200),
                   links=tuple(replace(link, name=clean_text(link.name, 40)) for link in chain.links))
