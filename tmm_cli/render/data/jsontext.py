"""JSON as the project writes it: strict (no NaN or Infinity), numbers as JSON numbers, rows of numbers on one line."""

from __future__ import annotations

import json
import math
from pathlib import Path


def json_safe(obj):
    """`obj` with every NaN/±Infinity replaced by None: JSON has no such numbers.

    >>> json_safe({"a": [1.0, float("nan")], "b": float("inf")})
    {'a': [1.0, None], 'b': None}
    """
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_safe(v) for v in obj]
    return obj


def json_text(obj) -> str:
    """Strict JSON (never a bare NaN or Infinity), indented by two spaces, UTF-8 as is; a list of
    plain values (a point of the profile, a row of numbers) stays on one line.

    Why not ``json.dumps(indent=2)``: it puts every number of the cam profile's 1 441 points on a
    line of its own (12 800 lines for variant 17, 4 000 here) and, indented, runs Python's own
    encoder instead of the C one.

    >>> print(json_text({"a": [[1.5, float("nan")], [2, 3]], "b": {"c": "ж", "d": [], "e": [["x"], [1]]}}))
    {
      "a": [
        [1.5, null],
        [2, 3]
      ],
      "b": {
        "c": "ж",
        "d": [],
        "e": [
          ["x"],
          [1]
        ]
      }
    }
    """
    out: list[str] = []
    _json_into(out, obj, "\n")
    return "".join(out)


_JSON_LEAF = json.JSONEncoder(ensure_ascii=False, allow_nan=False, separators=(", ", ": ")).encode


def _json_key(key) -> str:
    return _JSON_LEAF(key) if isinstance(key, str) else json.dumps({key: 0}, ensure_ascii=False)[1:-4]


def _numeric_row(row) -> bool:
    """A non-empty list of numbers (no text, so "], [" can only join two rows)."""
    return isinstance(row, (list, tuple)) and bool(row) and all(
        x is None or isinstance(x, (int, float)) for x in row)


def _json_into(out: list, obj, newline: str) -> None:
    """`obj` as indented JSON appended to `out`; `newline` is the line break with the current indent."""
    if isinstance(obj, dict) and obj:
        inner = newline + "  "
        sep = "{" + inner
        for key, value in obj.items():
            out.append(sep + _json_key(key) + ": ")
            _json_into(out, value, inner)
            sep = "," + inner
        out.append(newline + "}")
    elif isinstance(obj, (list, tuple)) and obj and all(_numeric_row(v) for v in obj):  # a table of numbers
        inner = newline + "  "
        try:
            text = _JSON_LEAF(obj)
        except ValueError:  # a NaN or an infinity in it
            text = _JSON_LEAF(json_safe(obj))
        out.append("[" + inner + text[1:-1].replace("], [", "]," + inner + "[") + newline + "]")
    elif isinstance(obj, (list, tuple)) and any(isinstance(v, (dict, list, tuple)) for v in obj):
        inner = newline + "  "
        sep = "[" + inner
        for value in obj:
            out.append(sep)
            _json_into(out, value, inner)
            sep = "," + inner
        out.append(newline + "]")
    else:  # a plain value, an empty container, or a list of plain values: one line
        try:
            out.append(_JSON_LEAF(obj))
        except ValueError:  # a NaN or an infinity in it
            out.append(_JSON_LEAF(json_safe(obj)))


def write_json(path: Path, obj) -> None:
    Path(path).write_text(json_text(obj) + "\n", encoding="utf-8")
