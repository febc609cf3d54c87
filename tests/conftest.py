import os
from pathlib import Path

import pytest

os.environ.setdefault("MPLBACKEND", "Agg")

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT.parent / "shared" / "seeds" / "001_c1d02a68c42b9b45.txt"


@pytest.fixture(scope="session")
def table():
    from tmm_cli.variants import load_table

    return load_table()
