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


def pytest_collection_modifyitems(config, items):
    """Tests marked `floors` (tests/test_floors.py: fresh venvs, minutes) run only when asked for:
    ``pytest -m floors`` or ``TMM_FLOORS=1``."""
    if os.environ.get("TMM_FLOORS") == "1" or "floors" in (config.getoption("markexpr") or ""):
        return
    skip = pytest.mark.skip(reason="installs the dependency floors and the newest releases in fresh venvs "
                                   "(minutes): pytest -m floors, or TMM_FLOORS=1")
    for item in items:
        if "floors" in item.keywords:
            item.add_marker(skip)
