"""The sources the note may cite, as ГОСТ 7.0.100-2018 entries (the list of references prints the
cited ones, in the order of their first citation)."""

# ГОСТ 7.0.100-2018 entries of the sources the note may cite
SOURCES = {
    "book": {
        "ru": "Пожбелко, В. И. Курсовое проектирование по теории механизмов и машин : учебное пособие. Ч. 2 / "
              "В. И. Пожбелко, П. Г. Веницкий, Н. И. Ахметшин ; под ред. В. И. Пожбелко. – Челябинск : Изд-во ЮУрГУ, "
              "2003. – 52 с.",
        "en": "Pozhbelko, V. I., Venitsky, P. G., Akhmetshin, N. I. Course design in the theory of mechanisms and "
              "machines: a textbook. Part 2 / ed. by V. I. Pozhbelko. Chelyabinsk: South Ural State University, 2003. "
              "52 p. (in Russian)",
    },
}
