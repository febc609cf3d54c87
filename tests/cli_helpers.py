"""Shared assertions of the CLI tests."""


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
