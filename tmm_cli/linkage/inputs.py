"""The mechanism's data from a small TOML file (`tmm linkage --input FILE [--variant N]`).

One mechanism, with the command's option names as keys (metres, rpm, degrees)::

    r1 = 0.10
    h = 0.04
    c = 0.0
    r2 = 0.08
    r3 = 0.30
    b = -0.04
    rpm = 60
    # omega = 6.2832, eps_crank = 0, positions = 12, at = 45

or a department's own table: one ``[variants.N]`` table per variant, top-level keys shared by all
(an option given on the command line beats the file)::

    rpm = 60
    [variants.1]
    r1 = 0.10
    ...

This module reads the file and checks its form; the numbers are checked by the core.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import TmmError
from ..limits import INPUT_FILE_BYTES

KEYS = ("r1", "h", "c", "r2", "r3", "b", "rpm", "omega", "eps_crank", "positions", "at")
MAX_BYTES = INPUT_FILE_BYTES  # 64 KiB (limits.py)
MAX_VARIANTS = 1000


def _check_values(table: dict, where: str) -> dict:
    out = {}
    for key, value in table.items():
        name = key.replace("-", "_")
        if name not in KEYS:
            raise TmmError(f"{where}: unknown key '{key}'; known keys: {', '.join(KEYS)}")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise TmmError(f"{where}: '{key}' must be a number, e.g. {key} = 0.1 (metres, with a decimal dot)")
        if name == "positions" and not isinstance(value, int):
            raise TmmError(f"{where}: 'positions' must be a whole number, e.g. positions = 12")
        out[name] = value
    return out


def parse_input(raw: bytes, path, variant: str | None = None) -> dict:
    """The keys of the TOML text `raw` (the file `path`, read by the command with
    tmm_cli.inputs.files.read_file) as a dict {key: number}; for a table of variants, those of
    `variant`.

    TmmError (one line) for a non-UTF-8 or malformed file, an unknown key, a value that is not a
    number, or a variant the file does not have.
    """
    path = Path(path)
    import tomllib

    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        raise TmmError(f"{path} is not UTF-8 text; save it as UTF-8") from None
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        raise TmmError(f"{path} is not valid TOML ({exc}); write lines like r1 = 0.10 (a decimal dot)") from None
    except ValueError:  # an integer of thousands of digits (Python's conversion limit)
        raise TmmError(f"{path} is not valid TOML (a number too long); write lines like r1 = 0.10 (a decimal dot)") from None
    if "crank" in data or "frame" in data:
        raise TmmError(f"{path} is a mechanism file; run tmm linkage {path} (without --input)")
    table = data.pop("variants", None)
    base = _check_values(data, str(path))
    if table is None:
        if variant is not None:
            raise TmmError(f"{path} has no [variants.N] tables; drop --variant or add the tables")
        return base
    if not isinstance(table, dict) or not all(isinstance(v, dict) for v in table.values()):
        raise TmmError(f"{path}: 'variants' must be tables such as [variants.1]")
    if len(table) > MAX_VARIANTS:
        raise TmmError(f"{path} has {len(table)} variants; at most {MAX_VARIANTS} are read")
    names = ", ".join(sorted(table, key=lambda s: (len(s), s))[:20]) + (" …" if len(table) > 20 else "")
    if variant is None:
        raise TmmError(f"{path} is a table of variants ({names}); choose one with --variant N")
    key = str(variant).strip()
    if key not in table and key.lstrip("0") in table:
        key = key.lstrip("0")
    if key not in table:
        raise TmmError(f"{path} has no variant {variant}; it has: {names}")
    merged = dict(base)
    merged.update(_check_values(table[key], f"{path} [variants.{key}]"))
    return merged
