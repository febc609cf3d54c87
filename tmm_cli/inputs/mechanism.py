"""A mechanism file (`tmm linkage MECH.toml`): read the TOML into its tables.

The form of the file is checked by :mod:`tmm_cli.linkage.mechanism_file` (the command hands it these
tables); here only the reading: a missing, oversized, non-UTF-8 or malformed file is one TmmError
line naming it.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import TmmError

MAX_BYTES = 256 * 1024


def read_mechanism_tables(path) -> dict:
    """The tables of the mechanism file at `path`, as tomllib reads them."""
    import tomllib

    path = Path(path)
    try:
        if path.stat().st_size > MAX_BYTES:
            raise TmmError(f"{path} is larger than 256 KiB; a mechanism file holds a few tables")
        data = tomllib.loads(path.read_bytes().decode("utf-8-sig"))
    except FileNotFoundError:
        raise TmmError(f"{path} does not exist; give the mechanism's TOML file (see docs/mechanism.md)") from None
    except IsADirectoryError:
        raise TmmError(f"{path} is a folder; give a TOML file") from None
    except UnicodeDecodeError:
        raise TmmError(f"{path} is not UTF-8 text; save it as UTF-8") from None
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        raise TmmError(f"{path} is not valid TOML ({exc}); see docs/mechanism.md for the form") from None
    except OSError as exc:
        raise TmmError(f"cannot read {path} ({exc.strerror})") from None
    return data
