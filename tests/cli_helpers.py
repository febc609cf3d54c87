"""Shared helpers and assertions of the CLI tests."""

import json

from click.testing import CliRunner

from tmm_cli.cli import cli


def run(*args):
    """`tmm ARGS` in process (numbers and paths given as any type)."""
    return CliRunner().invoke(cli, [str(a) for a in args])


def run_json(*args):
    """`tmm ARGS --json --no-plots --lang en`, which must succeed: its JSON document."""
    res = run(*args, "--json", "--no-plots", "--lang", "en")
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


def assert_one_line_error(res, *words):
    """A usage error as the project promises it: exit 2, one line `tmm: error: …` on stderr naming
    `words`, no traceback anywhere."""
    assert res.exit_code == 2, (res.exit_code, res.output)
    err = res.stderr.strip()
    assert "Traceback" not in res.output and "Traceback" not in err
    assert len(err.splitlines()) == 1, err
    assert err.startswith("tmm: error:")
    for w in words:
        assert w in err, (w, err)


def wait_for(predicate, timeout=60.0) -> bool:
    """Poll `predicate` every 20 ms until it holds (True) or `timeout` seconds pass (False)."""
    import time

    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.02)
    return False


def group_gone(pgid) -> bool:
    """Whether no process of the process group `pgid` is left (a run and all it started)."""
    import os

    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return True
    return False
