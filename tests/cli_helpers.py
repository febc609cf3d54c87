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
