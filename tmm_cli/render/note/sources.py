"""The sources the note may cite (the list of references prints the cited ones, in the order of
their first citation).

A source's entry is not a translation but a bibliographic record: ГОСТ Р 7.0.100-2018 (п. 4.8)
describes a resource in the language of its own imprint, so the textbook — a Russian book — has its
record in Russian, the Russian note's entry (data, kept here and allowed by the catalogue's test);
the English note gives the same record transliterated and translated (п. 4.8.1), marked "(in
Russian)".
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Source:
    record: str  # ГОСТ Р 7.0.100-2018, in the language of the resource
    english: str  # transliterated and translated, for the English note


SOURCES = {
    "book": Source(
        record="Пожбелко, В. И. Курсовое проектирование по теории механизмов и машин : учебное пособие. Ч. 2 / "
               "В. И. Пожбелко, П. Г. Веницкий, Н. И. Ахметшин ; под ред. В. И. Пожбелко. – Челябинск : Изд-во "
               "ЮУрГУ, 2003. – 52 с.",
        english="Pozhbelko, V. I., Venitsky, P. G., Akhmetshin, N. I. Course design in the theory of mechanisms and "
                "machines: a textbook. Part 2 / ed. by V. I. Pozhbelko. Chelyabinsk: South Ural State University, "
                "2003. 52 p. (in Russian)",
    ),
    # sheets 1 and 2 (the mechanism's structure, kinematics, forces, dynamics, flywheel): not in the book above
    "artobolevsky": Source(
        record="Артоболевский, И. И. Теория механизмов и машин : учебник для втузов / И. И. Артоболевский. – 4-е "
               "изд., перераб. и доп. – Москва : Наука, 1988. – 640 с.",
        english="Artobolevsky, I. I. Theory of mechanisms and machines: a textbook for technical universities. 4th "
                "ed. Moscow: Nauka, 1988. 640 p. (in Russian)",
    ),
    # the standards the note and the sheets follow (records without the imprint the project could not check)
    "gost16532": Source(
        record="ГОСТ 16532-70. Передачи зубчатые цилиндрические эвольвентные внешнего зацепления. Расчет "
               "геометрии : государственный стандарт Союза ССР : издание официальное.",
        english="GOST 16532-70. Involute external spur gear pairs. Calculation of geometry: state standard of the "
                "USSR. (in Russian)",
    ),
    "gost2104": Source(
        record="ГОСТ 2.104-2006. Единая система конструкторской документации. Основные надписи : межгосударственный "
               "стандарт : издание официальное : введен 2006-09-01.",
        english="GOST 2.104-2006. Unified system for design documentation. Title blocks: interstate standard. "
                "Introduced 2006-09-01. (in Russian)",
    ),
    "gost2302": Source(
        record="ГОСТ 2.302-68. Единая система конструкторской документации. Масштабы : межгосударственный стандарт : "
               "издание официальное : введен 1971-01-01.",
        english="GOST 2.302-68. Unified system for design documentation. Scales: interstate standard. Introduced "
                "1971-01-01. (in Russian)",
    ),
    "gost732": Source(
        record="ГОСТ 7.32-2017. Система стандартов по информации, библиотечному и издательскому делу. Отчет о "
               "научно-исследовательской работе. Структура и правила оформления : межгосударственный стандарт : "
               "издание официальное : введен 2018-07-01.",
        english="GOST 7.32-2017. System of standards on information, librarianship and publishing. The research "
                "report. Structure and rules of presentation: interstate standard. Introduced 2018-07-01. (in Russian)",
    ),
}


def source_text(lang: str) -> dict[str, str]:
    """Each source's entry in the note of `lang`: the record itself in a Russian note, else its English form."""
    return {key: s.record if lang == "ru" else s.english for key, s in SOURCES.items()}
