"""`python -m tmm_cli.render.note [FOLDER|FILE.typ]`: the same as `tmm note`."""

import sys

from ...errors import TmmError
from . import recompile

try:
    print(recompile(__import__("pathlib").Path(sys.argv[1] if len(sys.argv) > 1 else ".")))
except TmmError as exc:
    print(f"tmm: {exc}", file=sys.stderr)
    sys.exit(2)
