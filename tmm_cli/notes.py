"""Warnings and assumptions carried by result objects, as data (no language, no printing).

The core returns ``Note`` objects; :func:`tmm_cli.i18n.lang.note_text` turns each into a sentence
in Russian or English from the message catalogues (``i18n/messages_cam.py``,
``i18n/messages_gears.py``). A missing catalogue entry falls back to the code and parameters, so
no warning is ever lost.
"""

from __future__ import annotations

from dataclasses import field
from typing import Literal

from .records import record


@record
class Note:
    """One warning (a possible but poor design) or assumption (what the program chose)."""

    code: str
    level: Literal["warning", "assumption"] = "warning"
    params: tuple[tuple[str, object], ...] = field(default=())

    @classmethod
    def make(cls, code: str, level: Literal["warning", "assumption"] = "warning", **params) -> "Note":
        return cls(code=code, level=level, params=tuple(sorted(params.items())))

    @property
    def kwargs(self) -> dict:
        return dict(self.params)
