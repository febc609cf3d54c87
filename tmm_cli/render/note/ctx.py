"""What every part of the note needs: the result, the language, number formats and the figures."""

from __future__ import annotations

from dataclasses import dataclass, field

from ...i18n.numbers import num
from .doc import Doc


@dataclass
class Ctx:
    r: object  # ProjectResult
    lang: str
    figures: dict[str, str]  # figure name -> file the note embeds (empty without plots)
    doc: Doc = None  # type: ignore[assignment]
    used_figures: list[str] = field(default_factory=list)
    widths: dict[str, str] = field(default_factory=dict)

    def __post_init__(self):
        if self.doc is None:
            self.doc = Doc(self.lang)

    def t(self, en: str, ru: str) -> str:
        return ru if self.lang == "ru" else en

    def n(self, x, **kw) -> str:
        """A number for the text: decimal comma under ru, the typographic minus."""
        return num(x, self.lang, minus="−", **kw)

    def q(self, x, **kw) -> str:
        """A number inside typst math (a string, so that the decimal comma gets no space)."""
        return '"' + self.n(x, **kw) + '"'

    def qd(self, x, **kw) -> str:
        """An angle in degrees inside typst math."""
        return '"' + self.n(x, **kw) + '°"'

    def planets(self, k: int) -> str:
        """"4 сателлита" / "4 planets"."""
        from ...i18n.numbers import plural

        return plural(k, self.lang, {"one": "planet", "other": "planets"} if self.lang != "ru"
                      else {"one": "сателлит", "few": "сателлита", "many": "сателлитов"})

    @staticmethod
    def u(unit: str) -> str:
        """A unit after a value inside typst math."""
        return 'thin "' + unit + '"'

    def fig(self, name: str, caption: str) -> None:
        """Embed a figure if it was drawn (`--no-plots` draws none)."""
        file = self.figures.get(name)
        if file:
            self.doc.figure(name, file, caption, self.widths.get(name, "100%"))
            self.used_figures.append(name)

    def has(self, name: str) -> bool:
        return name in self.figures
