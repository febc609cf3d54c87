"""A mechanism file (`tmm linkage MECH.toml`): read the TOML into its tables.

The form of the file is checked by :mod:`tmm_cli.linkage.mechanism_file` (the command hands it these
tables); here only the reading: a missing, oversized, non-UTF-8 or malformed file is one TmmError
line naming it.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import TmmError

MAX_BYTES = 256 * 1024


def read_mechanism_tables(path) -> dict:
    """The tables of the mechanism file at `path`, as tomllib reads them."""
    import tomllib

    from .files import read_file

    path = Path(path)
    if not os.path.lexists(path):
        raise TmmError(f"{path} does not exist; give the mechanism's TOML file (see docs/mechanism.md)")
    if os.path.isdir(path):
        raise TmmError(f"{path} is a folder; give a TOML file")
    if os.stat(path).st_size > MAX_BYTES:  # said in the file's own words (read_file checks it again, on the open file)
        raise TmmError(f"{path} is larger than 256 KiB; a mechanism file holds a few tables")
    raw = read_file(path, str(path), MAX_BYTES)  # a regular file (a FIFO is refused, not waited on), size first
    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        raise TmmError(f"{path} is not UTF-8 text; save it as UTF-8") from None
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        raise TmmError(f"{path} is not valid TOML ({exc}); see docs/mechanism.md for the form") from None
    except ValueError:  # an integer of thousands of digits (Python's conversion limit)
        raise TmmError(f"{path} is not valid TOML (a number too long); see docs/mechanism.md for the form") from None
    if isinstance(data.get("name"), str):  # a person's text: one line where it enters (names.clean_text)
        from .names import clean_text

        data["name"] = clean_text(data["name"])
    return data
