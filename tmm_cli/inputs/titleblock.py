"""Who hands the project in: the fields of the title block (sheets) and the title page (note).

A student sets them once in ``tmm.toml`` in the current folder, or per run with ``--student``,
``--group``, ``--teacher``, ``--org``, ``--city``, ``--designation``; an option beats the file. Missing fields
stay empty: the sheets leave the cell blank, the note leaves a line to fill in by hand.

``tmm.toml``::

    student = "Иванов И. И."
    group = "П-243"
    teacher = "Петров П. П."
    org = "ЮУрГУ, кафедра ТММ"
    city = "Челябинск"                  # the note's title page, above the year
    # designation = "ТММ.03.17.00.00"   (default: built from the sheet and variant numbers)
"""

from __future__ import annotations

import datetime as _dt
import os
from dataclasses import replace
from pathlib import Path

from ..errors import TmmError
from ..records import record

FIELDS = ("student", "group", "teacher", "org", "city", "designation")
SETTINGS_FILE = "tmm.toml"
MAX_FIELD = 200  # characters; longer text is refused (a title block cell holds far less)


@record
class TitleFields:
    """The title-block / title-page fields; empty strings where the user gave nothing."""

    student: str = ""
    group: str = ""
    teacher: str = ""
    org: str = ""
    city: str = ""  # the note's title page: «Челябинск 2026»
    designation: str = ""
    year: int = 0

    def designation_for(self, sheet: int, variant: int) -> str:
        """The designation printed in the title block: the user's, or ``ТММ.<sheet>.<variant>.00.00``.

        >>> TitleFields().designation_for(3, 17)
        'ТММ.03.17.00.00'
        >>> TitleFields(designation="АТ-243.03.08.00.00").designation_for(4, 8)
        'АТ-243.03.08.00.00'
        """
        return self.designation or f"ТММ.{sheet:02d}.{variant:02d}.00.00"

    @property
    def the_year(self) -> int:
        return self.year or _dt.date.today().year


def _clean(value, name: str, source: str) -> str:
    if value is None:
        return ""
    if not isinstance(value, str):
        raise TmmError(f"{source}: '{name}' must be text in quotes, e.g. {name} = \"...\"")
    from .names import clean_text

    text = clean_text(value)  # one line: breaks and tabs as spaces, control characters dropped
    if len(text) > MAX_FIELD:
        raise TmmError(f"{source}: '{name}' is {len(text)} characters long; shorten it to {MAX_FIELD} or fewer")
    return text


def load_settings(folder: Path | None = None) -> dict[str, str]:
    """The title fields of ``tmm.toml`` in `folder` (default: the current folder); {} if none.

    Unknown keys are refused (a typo would otherwise leave a field silently blank).
    """
    path = Path(folder or ".") / SETTINGS_FILE
    if not os.path.lexists(path):
        return {}
    import tomllib

    from ..limits import SETTINGS_BYTES
    from .files import read_file

    raw = read_file(path, str(path), SETTINGS_BYTES)  # a regular file; its size checked before reading
    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        raise TmmError(f"{path} is not UTF-8 text; save it as UTF-8") from None
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        raise TmmError(f"{path} is not valid TOML ({exc}); write lines like student = \"Иванов И. И.\"") from None
    except ValueError:  # an integer of thousands of digits (Python's conversion limit)
        raise TmmError(f"{path} is not valid TOML (a number too long); write lines like year = 2026") from None
    unknown = sorted(set(data) - set(FIELDS) - {"year"})
    if unknown:
        raise TmmError(f"{path}: unknown key(s) {', '.join(unknown)}; known keys: {', '.join(FIELDS)}, year")
    out = {name: _clean(data.get(name), name, str(path)) for name in FIELDS if name in data}
    if "year" in data:
        year = data["year"]
        if not isinstance(year, int) or isinstance(year, bool) or not 1900 <= year <= 2999:
            raise TmmError(f"{path}: 'year' must be a year such as 2026")
        out["year"] = year
    return out


def title_fields(options: dict | None = None, folder: Path | None = None) -> TitleFields:
    """Merge ``tmm.toml`` and the command-line `options` (an option given beats the file)."""
    fields = TitleFields(**load_settings(folder))
    given = {k: _clean(v, k, "--" + k) for k, v in (options or {}).items() if k in FIELDS and v is not None}
    return replace(fields, **given)
