"""Russian texts of the command line: `--help` of every command and option, click's own messages
and our error messages. The English texts stay in the click decorators and the code; this is the
one catalogue that maps them to Russian.

To translate a new option, add one line to OPTIONS: its English help → its Russian help
(tests/test_i18n_cli.py fails for an option whose help has no entry here).
Imported only under ``--lang ru`` / a Russian locale, so ``tmm --help`` in English pays nothing.
"""

from __future__ import annotations

import re
from contextlib import contextmanager
from functools import cache

# English help of an option → Russian help ------------------------------------------------------
OPTIONS: dict[str, str] = {
    "Show the version and exit.": "Показать версию и выйти.",
    "Show this message and exit.": "Показать эту справку и выйти.",
    "Use your own table in the format of variants/table_1_2.csv.":
        "Взять свою таблицу заданий в формате variants/table_1_2.csv.",
    "Output language (default: from the locale).": "Язык вывода (по умолчанию — по локали системы).",
    "Variant number from Table 1.2 (1–68).": "Номер варианта по табл. 1.2 (1–68).",
    "Output folder (default ./tmm-out); files go to DIR/variant-NN/.":
        "Папка результатов (по умолчанию ./tmm-out); файлы пишутся в DIR/variant-NN/.",
    "Figure file format.": "Формат файлов рисунков.",
    "Do not draw figures (faster).": "Не строить рисунки (быстрее).",
    "Print only JSON on stdout.": "Вывести только JSON в стандартный вывод.",
    "Cam angle step of the printed tables [deg].": "Шаг угла поворота кулачка в таблицах [град].",
    'Student\'s name for the title block and the note, e.g. "Иванов И. И." (or in tmm.toml).':
        'Фамилия и инициалы студента для основной надписи и записки, например "Иванов И. И." (или в tmm.toml).',
    "Student's group (or in tmm.toml).": "Группа студента (или в tmm.toml).",
    "Teacher's name (or in tmm.toml).": "Фамилия и инициалы преподавателя (или в tmm.toml).",
    "University and department (or in tmm.toml).": "Вуз и кафедра (или в tmm.toml).",
    "Drawing designation (default: built from the sheet and variant numbers).":
        "Обозначение чертежа (по умолчанию — из номеров листа и варианта).",
    "Crank speed of the linkage n_кр [rpm] (default: the book's 220 rpm, stated in the output).":
        "Частота вращения кривошипа рычажного механизма n_кр [об/мин] (по умолчанию 220 об/мин, как в "
        "пособии; об этом сказано в выводе).",
    "Mean reduced moment M from sheet 2 [N·m], for the motor power (§2.6).":
        "Средний приведённый момент M с 2-го листа [Н·м] — для мощности двигателя (п. 2.6).",
    "Force the planetary ratio fraction of the book's procedure, e.g. 13/4.":
        "Задать дробь передаточного отношения редуктора для методики пособия, например 13/4.",
    "Allowed planetary ratio error [%].": "Допустимая погрешность передаточного отношения редуктора [%].",
    "Force the number of planets.": "Задать число сателлитов.",
    "Also compute the spur pair's mesh stiffness (beyond the course, informative; V. P. Tarasik's method).":
        "Рассчитать также жёсткость зацепления простой передачи (сверх программы курса, справочно; методика "
        "В. П. Тарасика).",
    "Report format written beside the figures.": "Формат отчёта, записываемого рядом с рисунками.",
    "Variants, e.g. 1-68 or 3,17,40.": "Варианты, например 1-68 или 3,17,40.",
    "CSV with columns student,variant[,crank_rpm][,torque].":
        "CSV со столбцами student,variant[,crank_rpm][,torque] (или студент,вариант,…).",
    "Parallel worker processes (default: number of cores).":
        "Число параллельных процессов (по умолчанию — по числу ядер).",
    "Per-variant report format.": "Формат отчёта для каждого варианта.",
    "Variant number (one student).": "Номер варианта (один студент).",
    "The student's numbers (TOML or CSV, keys in `tmm check --keys`).":
        "Результаты студента (TOML или CSV, ключи — в `tmm check --keys`).",
    "Class roster CSV (student,variant[,crank_rpm][,torque]).":
        "Список группы, CSV (student,variant[,crank_rpm][,torque]).",
    "Folder with one answers file per student (STUDENT.toml or STUDENT.csv).":
        "Папка с файлом результатов каждого студента (СТУДЕНТ.toml или СТУДЕНТ.csv).",
    "Tolerance for graphical quantities [%].": "Допуск для графически определяемых величин [%].",
    "List the answer keys and exit.": "Показать ключи результатов и выйти.",
    # the student's choices of the cam (issue 8) and the spur pair (issue 12)
    "Your base radius r0 of the pitch curve [mm] (checked, not replaced).":
        "Свой минимальный радиус кулачка r0 (радиус теоретического профиля) [мм] (проверяется, но не заменяется).",
    "Your offset e of a translating follower [mm] (e > 0: axis right of the cam centre).":
        "Свой эксцентриситет e поступательного толкателя [мм] (e > 0: ось толкателя правее центра кулачка).",
    "Your distance l_OC from the cam centre to the rocker pivot [mm].":
        "Своё межцентровое расстояние l_OC от центра кулачка до оси качающегося толкателя [мм].",
    "Rocker turns on the rise the same way as the cam or opposite.":
        "Качающийся толкатель на фазе удаления поворачивается в ту же сторону, что и кулачок (same), или в "
        "противоположную (opposite).",
    "Your roller radius [mm] (default: 0.2·r0, at most 0.8·ρ_min).":
        "Свой радиус ролика [мм] (по умолчанию 0,2·r0, не более 0,8·ρ_min).",
    "Also write the A1 drawing sheet (DXF and PDF, ESKD frame and title block).":
        "Записать также чертёж листа формата А1 (DXF и PDF, рамка и основная надпись по ЕСКД).",
    "Profile shifts of the spur pair (beyond the book), e.g. 0.3,-0.3; auto: no undercut, then a balanced split.":
        "Коэффициенты смещения x1, x2 простой передачи (сверх пособия), например 0.3,-0.3; auto — без подрезания, "
        "затем равномерное распределение.",
    "Required centre distance of the spur pair a_w [mm]: x1 + x2 from it, split as auto.":
        "Заданное межосевое расстояние простой передачи a_w [мм]: по нему x1 + x2, распределение как при auto.",
    "Which reducer to carry: the most accurate ratio among sets at most one tooth larger than the smallest, or the smallest.":
        "Какой редуктор принять: accurate — с наиболее точным передаточным отношением среди наборов чисел зубьев, "
        "не более чем на зуб больших наименьшего; smallest — наименьший.",
    # the note and the drawing sheets (issues 10, 11)
    "pdf: the explanatory note (note.pdf and its source note.typ); md: report.md.":
        "pdf — пояснительная записка (note.pdf и её исходный текст note.typ); md — отчёт report.md.",
    "A typst style file replacing the note's (see docs/note.md).":
        "Файл стиля typst вместо стиля записки (см. docs/note.md).",
    "Do not write the A1 drawing sheets sheet3/sheet4 (.dxf, .pdf).":
        "Не записывать чертежи листов 3 и 4 формата А1 (sheet3/sheet4, .dxf и .pdf).",
    # teachers (issue 7)
    "summary.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).":
        "summary.csv для русской (';', десятичная запятая) или английской электронной таблицы (по умолчанию — "
        "по --lang).",
    "Which sheet's required keys a student must give.":
        "Результаты какого листа студент обязан сдать (3, 4 или all — оба).",
    "Group check: folder for check.csv and check.md (default ./tmm-out).":
        "Проверка группы: папка для check.csv и check.md (по умолчанию ./tmm-out).",
    "check.csv for a Russian (';', decimal comma) or English spreadsheet (default: from --lang).":
        "check.csv для русской (';', десятичная запятая) или английской электронной таблицы (по умолчанию — "
        "по --lang).",
    # tmm linkage (issue 13): the article's symbols (Goban, Monková, Šmeringaiová)
    "Crank O21A [m].": "Длина кривошипа O21A [м].",
    "The slotted link's pivot O41 lies h below the crank centre O21 [m].":
        "Ось качания кулисы O41 лежит на h ниже центра кривошипа O21 [м].",
    "... and c to the left of it [m] (default 0; negative: to the right).":
        "… и на c левее него [м] (по умолчанию 0; отрицательное — правее).",
    "O41B: the point B of the link that drives the rod [m].":
        "Длина O41B до точки B кулисы, к которой присоединён шатун [м].",
    "Rod BC [m].": "Длина шатуна BC [м].",
    "The ram's guide is the line y = b [m] (y up from O21).":
        "Направляющая ползуна — прямая y = b [м] (y вверх от O21).",
    "Crank speed n21 [rpm] (φ21 grows with time).": "Частота вращения кривошипа n21 [об/мин] (φ21 растёт со временем).",
    "Crank speed ω21 [rad/s], instead of --rpm.": "Угловая скорость кривошипа ω21 [рад/с], вместо --rpm.",
    "Crank angular acceleration ε21 [rad/s²] (default 0: uniform).":
        "Угловое ускорение кривошипа ε21 [рад/с²] (по умолчанию 0 — равномерное вращение).",
    "Number of crank positions, from the start of the working stroke (default 12).":
        "Число положений кривошипа, начиная с начала рабочего хода (по умолчанию 12).",
    "Crank angle φ21 [deg] of the velocity and acceleration plans (default 45, the article's).":
        "Угол поворота кривошипа φ21 [град] для планов скоростей и ускорений (по умолчанию 45°, как в статье).",
    "Crank angle φ21 [deg], 0…360, of the velocity and acceleration plans (default 45, the article's).":
        "Угол поворота кривошипа φ21 [град], 0…360, для планов скоростей и ускорений (по умолчанию 45°, как в статье).",
    "TOML file with the same keys (r1, h, c, r2, r3, b, rpm, …); options beat it.":
        "Файл TOML с теми же ключами (r1, h, c, r2, r3, b, rpm, …); параметры командной строки важнее.",
    "With --input holding [variants.N] tables: the variant to take.":
        "Если в --input есть таблицы [variants.N]: номер варианта.",
    "Output folder (default ./tmm-out); files go to DIR/linkage/.":
        "Папка результатов (по умолчанию ./tmm-out); файлы пишутся в DIR/linkage/.",
    "With MECH.toml: the position of the velocity and acceleration plans, e.g. 3 or 7' (default: the middle of the "
    "working stroke).":
        "С файлом MECH.toml: положение для планов скоростей и ускорений, например 3 или 7' (по умолчанию — середина "
        "рабочего хода).",
    # tmm planetary (issue 12): S. N. Kavetsky's synthesis of the mechanism AA̅
    "Ratio i = i_1H^(4) of the AA̅ mechanism as a fraction, 0 < i < 1, e.g. 1/10.":
        "Передаточное отношение механизма AA̅ i = i_1H^(4) в виде дроби, 0 < i < 1, например 1/10.",
    "C = cos α_w12/cos α_w34 as a fraction, 1 < C < 1/(1 − i), e.g. 26/25.":
        "Отношение C = cos α_w12/cos α_w34 углов зацепления ступеней в виде дроби, 1 < C < 1/(1 − i), "
        "например 26/25.",
    "Number of planets k.": "Число сателлитов k.",
    "Module m [mm].": "Модуль зацепления m [мм].",
    "Shift of the sun 1.": "Коэффициент смещения x1 центрального колеса 1.",
    "Shift of the planet (x3 = x2).": "Коэффициент смещения x2 сателлита (x3 = x2).",
    "Fewest teeth of any wheel.": "Наименьшее допустимое число зубьев колеса.",
    "Most teeth of any wheel.": "Наибольшее допустимое число зубьев колеса.",
    "Take the K-th multiple of the smallest tooth set (default: the smallest within the limits).":
        "Взять K-й кратный набор чисел зубьев (по умолчанию — наименьший в заданных пределах).",
    "Output folder (default ./tmm-out); files go to DIR/planetary/.":
        "Папка результатов (по умолчанию ./tmm-out); файлы пишутся в DIR/planetary/.",
}

# command path → Russian help (the English one is the command's docstring) -----------------------
COMMANDS: dict[str, str] = {
    "tmm": "tmm — расчётная часть курсового проекта по ТММ (Пожбелко и др., 2003, ч. 2).\n\n"
           "Лист 3: синтез кулачкового механизма (`tmm cam`). Лист 4: синтез зубчатых механизмов (`tmm gears`). "
           "Оба листа сразу, с отчётом: `tmm project --variant 17`. Преподавателю: `tmm batch`, `tmm check`.",
    "tmm variants": "Таблица 1.2 (68 вариантов 3-го листа); `tmm variants show N` поясняет одну строку.",
    "tmm variants show": "Показать один вариант с пояснением каждого поля.",
    "tmm cam": "Лист 3: диаграммы движения толкателя, основные размеры, профиль кулачка, угол давления.",
    "tmm gears": "Лист 4: двигатель, разбивка передаточного отношения, синтез планетарного редуктора, простая "
                 "передача к кулачку.",
    "tmm project": "Весь проект для одного варианта: лист 4, затем лист 3, рисунки, results.json, пояснительная "
                   "записка и чертежи листов.",
    "tmm batch": "Преподавателю: расчёт многих вариантов или списка группы параллельно, со сводкой summary.csv.",
    "tmm check": "Преподавателю: проверка результатов студента по расчётным значениям.",
    "tmm linkage": "Лист 1: рычажный механизм — строение, положения, скорости, ускорения, планы, диаграммы.\n\n"
                   "MECH.toml описывает механизм так, как его строит формула строения: стойка, кривошип и группы "
                   "II класса RRR, RRP, RPR (docs/mechanism.md; примеры в docs/examples/). Без файла параметры "
                   "описывают кулисный механизм (механизм Витворта) из статьи J. Goban, K. Monková, "
                   "A. Šmeringaiová «The numerical and computer aided confrontation of kinematic analysis of "
                   "mechanism» (2010): начало в центре кривошипа O21, ось x вправо, y вверх; угол φ21 "
                   "отсчитывается от +y к +x. Примеры:\n\n"
                   "\b\n    tmm linkage docs/examples/shaper.toml --plan 3\n"
                   "    tmm linkage --r1 0.10 --h 0.04 --c 0 --r2 0.08 --r3 0.30 --b -0.04 --rpm 60",
    "tmm planetary": "Планетарный механизм AA̅ со смещёнными колёсами и разными углами зацепления ступеней "
                     "(С. Н. Кавецкий, 2010).\n\n"
                     "Числа зубьев по передаточному отношению i и C = cos α_w12/cos α_w34, общее межосевое "
                     "расстояние, углы зацепления и коэффициенты смещения обеих ступеней, проверка по блокирующим "
                     "контурам, картина скоростей и рисунок механизма.\n\n"
                     "Источник: С. Н. Кавецкий. Порядок проведения синтеза планетарного механизма AA̅ с учётом углов "
                     "зацепления зубчатых колёс первой и второй ступеней // Вестник НТУ «ХПИ». Тем. вып. "
                     "«Машиноведение и САПР». — 2010. Пример из статьи:\n\n"
                     "\b\ntmm planetary --ratio 1/10 --c 26/25 --planets 3 --module 5 --x1 -0.4 --x2 0.4",
    "tmm note": "Пересобрать пояснительную записку после правки: note.typ → note.pdf (по умолчанию — в текущей "
                "папке).",
}

# click's own messages (msgid → Russian); plural ones as (one, few, many) --------------------------
CLICK: dict[str, str] = {
    "Usage:": "Использование:",
    "Options": "Параметры",
    "Commands": "Команды",
    "Positional arguments": "Позиционные аргументы",
    "Show this message and exit.": "Показать эту справку и выйти.",
    "Show the version and exit.": "Показать версию и выйти.",
    "%(prog)s, version %(version)s": "%(prog)s, версия %(version)s",
    "default: {default}": "по умолчанию: {default}",
    "required": "обязательно",
    "(dynamic)": "(вычисляется)",
    "env var: {var}": "переменная окружения: {var}",
    "deprecated": "устарело",
    "Aborted!": "Прервано.",
    "Missing command.": "Не указана команда.",
    "Missing argument": "Не задан аргумент",
    "Missing option": "Не задан параметр",
    "Missing parameter": "Не задан параметр",
    "Missing {param_type}": "Не задан {param_type}",
    "Missing parameter: {param_name}": "Не задан параметр: {param_name}",
    "argument": "аргумент",
    "option": "параметр",
    "parameter": "параметр",
    "Invalid value for {param_hint}: {message}": "Недопустимое значение {param_hint}: {message}",
    "Invalid value: {message}": "Недопустимое значение: {message}",
    "No such option: {name}": "Нет такого параметра: {name}",
    "No such option {name!r}.": "Нет такого параметра {name!r}.",
    "No such command {name!r}.": "Нет такой команды {name!r}.",
    "Option {name!r} does not take a value.": "Параметр {name!r} не принимает значения.",
    "Argument {name!r} takes {nargs} values.": "Аргумент {name!r} принимает {nargs} значения.",
    "Error: {message}": "Ошибка: {message}",
    "Try '{command} {option}' for help.": "Справка: '{command} {option}'.",
    "{value!r} is not a valid {number_type}.": "{value!r} — не число.",
    "{value} is not in the range {range}.": "{value} вне диапазона {range}.",
    "{name} {filename!r} does not exist.": "{name} {filename!r} не существует.",
    "{name} {filename!r} is a directory.": "{name} {filename!r} — это папка.",
    "{name} {filename!r} is a file.": "{name} {filename!r} — это файл.",
    "{name} {filename!r} is not readable.": "{name} {filename!r} недоступен для чтения.",
    "{name} {filename!r} is not writable.": "{name} {filename!r} недоступен для записи.",
    "file": "Файл",
    "directory": "Папка",
    "path": "Путь",
    "Could not open file {filename!r}: {message}": "Не удалось открыть файл {filename!r}: {message}",
    "Value must be an iterable.": "Значение должно быть списком.",
}
CLICK_PLURAL: dict[str, tuple[str, str]] = {
    "Got unexpected extra argument ({args})": ("Лишний аргумент ({args})", "Лишние аргументы ({args})"),
    "Option {name!r} requires an argument.": ("Параметру {name!r} нужно значение.",
                                              "Параметру {name!r} нужно {nargs} значения."),
    "{value!r} is not {choice}.": ("{value!r}: можно только {choice}.", "{value!r} не из списка: {choices}."),
    "Did you mean {possibility}?": ("Может быть, {possibility}?", "(Может быть, одно из: {possibilities}?)"),
    "Takes {nargs} values but 1 was given.": ("Нужно {nargs} значения, задано 1.",
                                              "Нужно {nargs} значения, задано {len}."),
}

# our own errors: English pattern → Russian template ----------------------------------------------
ERRORS: list[tuple[str, str]] = [
    (r"variant '(?P<v>.*)' is not a number; give a variant number such as 17",
     "вариант '{v}' — не число; укажите номер варианта, например 17"),
    (r"variant (?P<n>\d+) is not in the table; choose a variant from (?P<lo>\d+) to (?P<hi>\d+)",
     "варианта {n} нет в таблице; выберите вариант от {lo} до {hi}"),
    (r"variants file (?P<p>.*) does not exist; check the path", "файл заданий {p} не существует; проверьте путь"),
    (r"variants file (?P<p>.*) cannot be read \((?P<why>.*)\); check the file",
     "файл заданий {p} не читается ({why}); проверьте файл"),
    (r"crank speed must be a positive number of rpm, got (?P<x>.*); give the crank speed of your linkage "
     r"\(sheet 1\), e\.g\. --crank-rpm 220",
     "частота вращения кривошипа должна быть положительной, задано {x}; укажите частоту кривошипа вашего "
     "рычажного механизма (лист 1), например --crank-rpm 220"),
    (r"crank speed (?P<x>.*) rpm is too high: no standard motor \(720, 920, 1420, 2880 rpm\) has n_d ≥ 3·n_cr = "
     r"(?P<y>.*) rpm; use a crank speed of at most 960 rpm",
     "частота кривошипа {x} об/мин слишком велика: ни один стандартный двигатель (720, 920, 1420, 2880 об/мин) "
     "не даёт n_д ≥ 3·n_кр = {y} об/мин; задайте не более 960 об/мин"),
    (r"mean reduced moment must be a non-negative number of N·m, got (?P<x>.*); give M from sheet 2, e\.g\. "
     r"--torque 100",
     "приведённый момент должен быть неотрицательным числом Н·м, задано {x}; возьмите M со 2-го листа, "
     "например --torque 100"),
    (r"ratio tolerance must be a non-negative percentage, got (?P<x>.*); the book uses 5, e\.g\. --tolerance 5",
     "допуск передаточного отношения должен быть неотрицательным, задано {x}; в пособии 5 %, например "
     "--tolerance 5"),
    (r"number of planets must be a whole number ≥ 1, got (?P<x>.*); e\.g\. --planets 3",
     "число сателлитов должно быть целым ≥ 1, задано {x}; например --planets 3"),
    (r"cannot read the ratio (?P<x>.*): write it as a fraction of two positive whole numbers, e\.g\. --ratio 13/4",
     "не удалось прочитать дробь {x}: запишите её как дробь двух целых положительных чисел, например "
     "--ratio 13/4"),
    (r"the ratio (?P<x>.*) has a zero in it: write it as a fraction of two positive whole numbers, e\.g\. "
     r"--ratio 13/4",
     "в дроби {x} есть ноль: запишите её как дробь двух целых положительных чисел, например --ratio 13/4"),
    (r"the forced ratio (?P<f>\S+) must be greater than 1 for a reducer, e\.g\. --ratio 13/4",
     "заданная дробь {f} должна быть больше 1 (редуктор), например --ratio 13/4"),
    (r"the forced ratio (?P<f>\S+) = (?P<x>\S+) is (?P<e>\S+) % off the required i_pl = n_d/n_cr = (?P<r>\S+) = "
     r"(?P<i>\S+), outside ±(?P<t>\S+) %; use a fraction near it \(e\.g\. (?P<near>.*)\) or widen --tolerance",
     "заданная дробь {f} = {x} отличается от требуемого i_пл = n_д/n_кр = {r} = {i} на {e} %, это вне ±{t} %; "
     "возьмите близкую дробь (например {near}) или увеличьте --tolerance"),
    (r"table step '(?P<x>.*)' is not a number; give degrees, e\.g\. 10",
     "шаг таблицы '{x}' — не число; задайте его в градусах, например 10"),
    (r"table step (?P<x>.*)° is out of range; give a step above 0 and at most 30 degrees \(the book uses 10\)",
     "шаг таблицы {x}° вне допустимого диапазона; задайте шаг больше 0 и не более 30° (в пособии 10°)"),
    (r"cannot write to output folder (?P<p>.*) \((?P<why>.*)\); choose a writable folder with --out",
     "нельзя записать в папку {p} ({why}); укажите доступную для записи папку в --out"),
    (r"cannot write into (?P<p>.*) \((?P<why>.*)\); choose a writable folder with --out",
     "нельзя записать в {p} ({why}); укажите доступную для записи папку в --out"),
    (r"give exactly one of --variants \(e\.g\. 1-68\) or --roster FILE",
     "задайте что-то одно: --variants (например 1-68) или --roster ФАЙЛ"),
    (r"--jobs is (?P<x>.*); give 1 or more worker processes", "--jobs = {x}; задайте 1 или больше процессов"),
    (r"--rtol is (?P<x>.*); give a positive tolerance in percent", "--rtol = {x}; задайте положительный допуск в процентах"),
    (r"group check needs both --roster FILE and --answers-dir DIR",
     "для проверки группы нужны оба параметра: --roster ФАЙЛ и --answers-dir ПАПКА"),
    (r"give --variant N and --answers FILE \(or --roster FILE with --answers-dir DIR\)",
     "задайте --variant N и --answers ФАЙЛ (или --roster ФАЙЛ и --answers-dir ПАПКА)"),
    (r"--variants range '(?P<p>.*)' runs backwards; write it as (?P<q>.*)",
     "диапазон --variants '{p}' записан в обратном порядке; запишите {q}"),
    (r"--variants '(?P<s>.*)' is not a list like 1-68 or 3,17,40; fix '(?P<p>.*)'",
     "--variants '{s}' — не список вида 1-68 или 3,17,40; исправьте '{p}'"),
    (r"roster (?P<p>.*) cannot be read \((?P<why>.*)\); check the path",
     "список группы {p} не читается ({why}); проверьте путь"),
    (r"answers file (?P<p>.*) cannot be read \((?P<why>.*)\); check the path",
     "файл результатов {p} не читается ({why}); проверьте путь"),
    (r"answers folder (?P<d>.*) does not exist; give the folder with one file per student",
     "папки результатов {d} нет; укажите папку с файлом каждого студента"),
    (r"no answers file (?P<s>.*)\.toml or \.csv in (?P<d>.*)", "в {d} нет файла результатов {s}.toml или .csv"),
    (r"the answers file has no values; write lines like r0_mm = 41\.2 \(see `tmm check --keys`\)",
     "в файле результатов нет значений; запишите строки вида r0_mm = 41.2 (см. `tmm check --keys`)"),
    (r"tmm (?P<c>linkage|planetary) is not built yet", "команда tmm {c} ещё не готова"),
    (r"no cam centre keeps the pressure angle within (?P<x>\S+)°; allow a larger nu_max or a longer phase",
     "ни одно положение центра кулачка не удерживает угол давления в пределах {x}°; увеличьте ν_max или фазу"),
    (r"(?P<p>.*) is not valid TOML \((?P<why>.*)\); write lines like student = \"Иванов И\. И\.\"",
     "{p} — не TOML ({why}); пишите строки вида student = \"Иванов И. И.\""),
    (r"(?P<p>.*) is not UTF-8 text; save it as UTF-8", "{p} — не текст в UTF-8; сохраните его в UTF-8"),
    (r"cam speed must be a non-zero number of rpm, got (?P<x>.*); take n_k from Table 1\.2",
     "частота вращения кулачка должна быть ненулевой, задано {x}; возьмите n_k из табл. 1.2"),
    (r"(?P<w>.*): field '(?P<f>.*)' is '(?P<r>.*)', not a number; fix the table",
     "{w}: поле '{f}' = '{r}' — не число; исправьте таблицу"),
    (r"(?P<w>.*): field '(?P<f>.*)' is empty; fill it in", "{w}: поле '{f}' пустое; заполните его"),
    (r"(?P<w>.*): field '(?P<f>.*)' is '(?P<r>.*)'; it must be a whole number",
     "{w}: поле '{f}' = '{r}'; нужно целое число"),
    (r"(?P<s>.*): missing column\(s\) (?P<m>.*); the header must be (?P<h>.*)",
     "{s}: нет столбцов {m}; заголовок должен быть {h}"),
    (r"(?P<s>.*): no variants in the table; add rows under the header",
     "{s}: в таблице нет вариантов; добавьте строки под заголовком"),
    (r"(?P<s>.*) line (?P<n>\d+): variant (?P<v>\d+) appears twice; keep one row",
     "{s}, строка {n}: вариант {v} встречается дважды; оставьте одну строку"),
    (r"(?P<w>.*): the phase angles sum to (?P<t>.*) deg, over 360; shorten the rise, dwell or return",
     "{w}: сумма фазовых углов {t}° больше 360°; сократите удаление, стояние или возвращение"),
    (r"(?P<p>.*) is not valid TOML \((?P<why>.*)\); write lines like r0_mm = 41\.2, with a dot for decimals",
     "{p} — не TOML ({why}); пишите строки вида r0_mm = 41.2, с точкой в дробных числах"),
    (r"(?P<w>.*): '(?P<r>.*)' is not a number; write a plain number", "{w}: '{r}' — не число; запишите обычное число"),
    (r"(?P<w>.*): '(?P<r>.*)' is not a number", "{w}: '{r}' — не число"),
    (r"roster (?P<p>.*) has no column\(s\) (?P<m>.*); the header must be student,variant\[,crank_rpm\]\[,torque\]",
     "в списке группы {p} нет столбцов {m}; заголовок: student,variant[,crank_rpm][,torque]"),
    (r"(?P<s>.*): '(?P<n>.*)' is (?P<k>\d+) characters long; shorten it to (?P<m>\d+) or fewer",
     "{s}: '{n}' длиной {k} символов; сократите до {m}"),
    (r"(?P<p>.*): unknown key\(s\) (?P<u>.*); known keys: (?P<k>.*)", "{p}: неизвестные ключи {u}; допустимые: {k}"),
    (r"cannot read (?P<p>.*) \((?P<why>.*)\)", "не удалось прочитать {p} ({why})"),
    # click's Path type: its word File/Directory/Path is fixed in English when the option is declared
    (r"Directory (?P<p>'.*') — это файл\.", "{p} — это файл, а нужна папка"),
    (r"File (?P<p>'.*') — это папка\.", "{p} — это папка, а нужен файл"),
    (r"(?:File|Directory|Path) (?P<p>'.*') не существует\.", "{p} не существует"),
    (r"(?:File|Directory|Path) (?P<p>'.*') недоступен для чтения\.", "{p} недоступен для чтения"),
    (r"(?:File|Directory|Path) (?P<p>'.*') недоступен для записи\.", "{p} недоступен для записи"),
]

# our errors from a few templates: English template → Russian ({name} matches any text) ------------
# The modules build their messages from these f-strings; a template here is the f-string with its
# fields named. Listed before ERRORS' generic patterns (the first match wins).
TEMPLATES: list[tuple[str, str]] = [
    ("roster line {n}: {rest}", "список группы, строка {n}: {rest}"),  # a roster row's error (batch.py)
    # limits.py: the options' ranges (click type Range) and check_range / check_int_range
    ("'{v}' is not a whole number; give one from {lo} to {hi}", "'{v}' — не целое число; задайте целое от {lo} до {hi}"),
    ("{v} is out of range; give a whole number from {lo} to {hi} (docs/limits.md)",
     "{v} вне допустимого диапазона; задайте целое число от {lo} до {hi} (docs/limits.md)"),
    ("'{v}' is not a number; give one from {lo} to {hi}", "'{v}' — не число; задайте число от {lo} до {hi}"),
    ("{v} is out of range; give a number from {lo} to {hi} (docs/limits.md)",
     "{v} вне допустимого диапазона; задайте число от {lo} до {hi} (docs/limits.md)"),
    ("{w} is '{v}', not a number; give a number from {lo} to {hi} per cent",
     "{w} = '{v}' — не число; задайте число от {lo} до {hi} %"),
    ("{w} is '{v}', not a number; give a number from {lo} to {hi}", "{w} = '{v}' — не число; задайте число от {lo} до {hi}"),
    ("{w} is {v}; give a finite number from {lo} to {hi} per cent", "{w} = {v}; задайте конечное число от {lo} до {hi} %"),
    ("{w} is {v}; give a finite number from {lo} to {hi}", "{w} = {v}; задайте конечное число от {lo} до {hi}"),
    ("{w} is {v}; give a number from {lo} to {hi} per cent", "{w} = {v}; задайте число от {lo} до {hi} %"),
    ("{w} is {v}; give a number from {lo} to {hi}", "{w} = {v}; задайте число от {lo} до {hi}"),
    ("{w} is '{v}'; give a whole number from {lo} to {hi}", "{w} = '{v}'; задайте целое число от {lo} до {hi}"),
    ("{w} is {v}; give a whole number from {lo} to {hi}", "{w} = {v}; задайте целое число от {lo} до {hi}"),
    # check.py: a student's answers file
    ("{w}: the key is not a name like r0_mm (letters, digits, '_'); see `tmm check --keys`",
     "{w}: ключ — не имя вида r0_mm (буквы, цифры, «_»); см. `tmm check --keys`"),
    ("{w}: expected key,value", "{w}: ожидается ключ,значение"),
    ("{w}: key {k} appears twice (first on line {n}); keep one",
     "{w}: ключ {k} встречается дважды (впервые в строке {n}); оставьте один"),
    ("{w} is not valid TOML (too deeply nested or a number too long); write lines like r0_mm = 41.2",
     "{w} — не TOML (слишком глубокая вложенность или слишком длинное число); пишите строки вида r0_mm = 41.2"),
    ("{w} has {n} keys, over the limit of {m}; write only the answers",
     "в {w} {n} ключей, больше предела {m}; запишите только результаты"),
    ("{w} ({k}): write a plain number, not a table or list", "{w} ({k}): запишите обычное число, а не таблицу или список"),
    ("answers file {f} is a link or lies outside {d}; put the student's own file there",
     "файл результатов {f} — ссылка или лежит вне {d}; положите туда собственный файл студента"),
    ("answers file {f} is not a regular file", "файл результатов {f} — не обычный файл"),
    ("no answers file {s}.toml or {s2}.csv in {d}", "в {d} нет файла результатов {s}.toml или {s2}.csv"),
    # batch.py: --variants and the roster
    ("--variants is {n} characters long, over {m}; give ranges like 1-68",
     "--variants длиной {n} символов, больше {m}; задайте диапазоны вида 1-68"),
    ("--variants {s}: {text} not in the table (it has variants {lo}-{hi}); give numbers from {lo2} to {hi2}",
     "--variants {s}: {text} нет в таблице (в ней варианты {lo}–{hi}); задайте номера от {lo2} до {hi2}"),
    ("--variants: variant {n} is not in the table; choose from {lo} to {hi}",
     "--variants: варианта {n} нет в таблице; выберите от {lo} до {hi}"),
    ("--variants asks for over {m} variants; give a shorter list", "--variants: больше {m} вариантов; сократите список"),
    ("--variants asks for {n} variants, over {m}; split the batch",
     "--variants: {n} вариантов, больше {m}; разделите расчёт на части"),
    ("roster {p} has no column(s) {m}; the header must be student,variant[,group][,crank_rpm][,torque] "
     "(or студент;вариант;группа;n_кр;момент)",
     "в списке группы {p} нет столбцов {m}; заголовок должен быть student,variant[,group][,crank_rpm][,torque] "
     "(или студент;вариант;группа;n_кр;момент)"),
    ("the student column is empty", "столбец студента пуст"),
    ("the variant column is empty", "столбец варианта пуст"),
    ("the name has no letter or digit to name a file by", "в имени нет ни буквы, ни цифры, чтобы назвать по нему файл"),
    ("'{s}' gives the same file name '{f}' as '{s2}' on line {n} (names differing only in case or punctuation share "
     "one file); make the names differ",
     "'{s}' даёт то же имя файла '{f}', что и '{s2}' в строке {n} (имена, различающиеся только регистром или "
     "знаками препинания, делят один файл); сделайте имена различными"),
    ("roster {p} has a header but no students; add one row per student",
     "в списке группы {p} есть заголовок, но нет студентов; добавьте по строке на студента"),
    # tabular.py: reading CSV and numbers
    ("{w} starts like UTF-16 but cannot be decoded; save it again as CSV UTF-8",
     "{w} начинается как UTF-16, но не декодируется; сохраните его заново как CSV UTF-8"),
    ("{w} starts like UTF-8 but cannot be decoded; save it again as CSV UTF-8",
     "{w} начинается как UTF-8, но не декодируется; сохраните его заново как CSV UTF-8"),
    ("{w} is neither UTF-8 nor cp1251 text; save it as CSV UTF-8",
     "{w} — текст не в UTF-8 и не в cp1251; сохраните его как CSV UTF-8"),
    ("{w} is not a text file (it holds NUL bytes); save it as CSV UTF-8",
     "{w} — не текстовый файл (в нём нулевые байты); сохраните его как CSV UTF-8"),
    ("{w} is {n} bytes, over the limit of {m} bytes; is it the right file? (limits: docs/limits.md)",
     "{w} занимает {n} байт, больше предела {m} байт; тот ли это файл? (пределы: docs/limits.md)"),
    ("{w} is over the limit of {m} bytes; is it the right file? (limits: docs/limits.md)",
     "{w} больше предела {m} байт; тот ли это файл? (пределы: docs/limits.md)"),
    ("{w} is a folder, not a file; give the file", "{w} — папка, а не файл; укажите файл"),
    ("{w} does not exist; check the path", "{w} не существует; проверьте путь"),
    ("{w} cannot be read ({why}); check the path", "{w} не читается ({why}); проверьте путь"),
    ("{w} has more than {m} rows, over the limit; split it (limits: docs/limits.md)",
     "в {w} больше {m} строк, это сверх предела; разделите его (пределы: docs/limits.md)"),
    ("{w} is not valid CSV ({why}); check the quotes", "{w} — не CSV ({why}); проверьте кавычки"),
    ("{w} is not a number; write a plain number (decimal comma or dot)",
     "{w} — не число; запишите обычное число (с десятичной запятой или точкой)"),
    ("{w} is a number too large to be an answer; write a plain number",
     "{w} — слишком большое число для результата; запишите обычное число"),
    ("{w} is not a finite number of sensible size; write a plain number",
     "{w} — не конечное число разумной величины; запишите обычное число"),
    ("{w} is not a number; write a plain number", "{w} — не число; запишите обычное число"),
    # variants.py: a --variants-file
    ("{w}: field '{f}' is '{r}'; give a finite number", "{w}: поле '{f}' = '{r}'; задайте конечное число"),
    ("{w}: scheme is {s}; it must be 1, 2, 3 or 4", "{w}: схема {s}; допустимы 1, 2, 3 или 4"),
    ("{w}: law is {s}; it must be 1, 2, 3 or 4", "{w}: закон движения {s}; допустимы 1, 2, 3 или 4"),
    ("{w}: nu_max_deg is {x}; it must lie between 0 and 90 degrees",
     "{w}: nu_max_deg = {x}; допустимый угол давления — от 0 до 90°"),
    ("{w}: n_cam_rpm is 0; give the cam speed (negative = clockwise)",
     "{w}: n_cam_rpm = 0; задайте частоту вращения кулачка (отрицательная — по часовой стрелке)"),
    ("{w}: n_cam_rpm is {x}; give a cam speed of {lo} to {hi} rpm either way (negative = clockwise; docs/limits.md)",
     "{w}: n_cam_rpm = {x}; задайте частоту вращения кулачка от {lo} до {hi} об/мин в любую сторону "
     "(отрицательная — по часовой стрелке; docs/limits.md)"),
    ("{w}: scheme {s} is a rocker; fill in l_bc_m", "{w}: схема {s} — с качающимся толкателем; заполните l_bc_m"),
    ("{w}: l_bc_m is {x}; the rocker length must be positive", "{w}: l_bc_m = {x}; длина качающегося толкателя должна быть положительной"),
    ("{w}: l_bc_m is {x}; give a rocker length of {lo} to {hi} m (docs/limits.md)",
     "{w}: l_bc_m = {x}; задайте длину качающегося толкателя от {lo} до {hi} м (docs/limits.md)"),
    ("{w}: scheme {s} is a rocker; give gamma_max_deg, leave s_max_m empty",
     "{w}: схема {s} — с качающимся толкателем; задайте gamma_max_deg, а s_max_m оставьте пустым"),
    ("{w}: gamma_max_deg is {x}; the swing must lie between 0 and 90 degrees",
     "{w}: gamma_max_deg = {x}; наибольший угол поворота качающегося толкателя должен быть от 0 до 90°"),
    ("{w}: scheme {s} has a translating follower; leave l_bc_m empty",
     "{w}: схема {s} — с поступательным толкателем; оставьте l_bc_m пустым"),
    ("{w}: scheme {s} has a translating follower; give s_max_m, leave gamma_max_deg empty",
     "{w}: схема {s} — с поступательным толкателем; задайте s_max_m, а gamma_max_deg оставьте пустым"),
    ("{w}: s_max_m is {x}; the stroke must be positive", "{w}: s_max_m = {x}; ход толкателя должен быть положительным"),
    ("{w}: s_max_m is {x}; give a stroke of {lo} to {hi} m (docs/limits.md)",
     "{w}: s_max_m = {x}; задайте ход толкателя от {lo} до {hi} м (docs/limits.md)"),
    ("{w}: {f} is {x}; phase angles cannot be negative", "{w}: {f} = {x}; фазовые углы не могут быть отрицательными"),
    ("{w}: {f} is 0; rise and return need a positive angle",
     "{w}: {f} = 0; фазы удаления и возвращения должны иметь положительный угол"),
    ("{w}: more than {m} variants, over the limit; split the table (docs/limits.md)",
     "{w}: больше {m} вариантов, это сверх предела; разделите таблицу (docs/limits.md)"),
    # titleblock.py: tmm.toml
    ("{w}: '{k}' must be text in quotes, e.g. {k2} = \"...\"", "{w}: '{k}' должно быть текстом в кавычках, например {k2} = \"...\""),
    ("{w} is larger than 64 KiB; it should hold only the title fields",
     "{w} больше 64 КиБ; в нём должны быть только поля основной надписи"),
    ("{w}: 'year' must be a year such as 2026", "{w}: 'year' должен быть годом, например 2026"),
    # output/folder.py: the output folder
    ("cannot write to output folder {p} ({q} is not a folder); choose a folder with --out",
     "нельзя записать в папку результатов {p} ({q} — не папка); укажите папку в --out"),
    ("cannot write to output folder {p} (Permission denied); choose a writable folder with --out",
     "нельзя записать в папку результатов {p} (нет прав доступа); укажите доступную для записи папку в --out"),
    ("cannot create output folder {p} ({why}); choose a writable folder with --out",
     "не удалось создать папку результатов {p} ({why}); укажите доступную для записи папку в --out"),
    ("another {what} is writing into {p}; wait for it to finish or choose another --out",
     "в {p} уже пишет другой процесс ({what}); дождитесь его окончания или укажите другую папку в --out"),
    ("{p} was not written by tmm (it is not in {m}); tmm never overwrites such a file: move it away or choose another "
     "--out",
     "файл {p} записан не программой tmm (его нет в {m}); tmm не перезаписывает такие файлы: переместите его или "
     "укажите другую папку в --out"),
    ("{p} is a symbolic link; tmm writes only into real folders: remove the link or choose another --out",
     "{p} — символическая ссылка; tmm пишет только в настоящие папки: удалите ссылку или укажите другую папку в --out"),
    ("{p} exists and is not a folder; move it away or choose another --out",
     "{p} существует и не является папкой; переместите его или укажите другую папку в --out"),
    ("cannot create {p} ({why}); choose a writable folder with --out",
     "не удалось создать {p} ({why}); укажите доступную для записи папку в --out"),
    ("{p} is not a real folder; choose another --out", "{p} — не настоящая папка; укажите другую папку в --out"),
    ("cannot write {p} ({why}); choose a writable folder with --out",
     "не удалось записать {p} ({why}); укажите доступную для записи папку в --out"),
    # gears/shifted.py: --shift and --aw
    ("the shift sum x1 + x2 = {x} is too negative for z1 + z2 = {z}: inv α_w would be {v} ≤ 0; use a larger shift sum "
     "(x1 + x2 > {m})",
     "сумма коэффициентов смещения x1 + x2 = {x} слишком отрицательна для z1 + z2 = {z}: inv α_w = {v} ≤ 0; "
     "увеличьте сумму смещений (x1 + x2 > {m})"),
    ("centre distance a_w must be a positive number of mm, got {x}; e.g. --aw {e}",
     "межосевое расстояние a_w должно быть положительным числом мм, задано {x}; например --aw {e}"),
    ("centre distance a_w = {x} mm cannot be reached: no shift sum brings z1 = {z1}, z2 = {z2}, m = {m} mm closer than "
     "a·cos α = {c} mm (and practically not much below a = {a} mm); give --aw of about {a2} mm or more",
     "межосевое расстояние a_w = {x} мм недостижимо: никакая сумма смещений не сблизит колёса z1 = {z1}, z2 = {z2}, "
     "m = {m} мм ближе a·cos α = {c} мм (а практически — ненамного меньше a = {a} мм); задайте --aw около {a2} мм "
     "или больше"),
    ("shift {n} must be a number, got {v}; e.g. --{e}", "коэффициент смещения {n} должен быть числом, задано {v}; например --{e}"),
    ("tooth numbers must be positive, got {z1}, {z2}", "числа зубьев должны быть положительными, заданы {z1}, {z2}"),
    ("a tip circle lies inside its base circle: the shifts are far too negative for these teeth",
     "окружность вершин лежит внутри основной окружности: смещения слишком отрицательны для этих чисел зубьев"),
    ("the shift sum x1 + x2 = {x} is so large that the tip reduction Δy = {y} puts a tip circle inside its base circle; "
     "take a smaller shift sum (a_w closer to a = {a} mm)",
     "сумма смещений x1 + x2 = {x} так велика, что уравнительное смещение Δy = {y} уводит окружность вершин внутрь "
     "основной окружности; уменьшите сумму смещений (a_w ближе к a = {a} мм)"),
    ("cannot read --shift {t}: write two shift coefficients with decimal dots, e.g. --shift 0.3,-0.3, or --shift auto",
     "не удалось прочитать --shift {t}: запишите два коэффициента смещения с десятичной точкой, например "
     "--shift 0.3,-0.3, или --shift auto"),
    ("--shift {t} must be two finite numbers, e.g. --shift 0.3,-0.3",
     "--shift {t}: нужны два конечных числа, например --shift 0.3,-0.3"),
    ("--shift {s} gives a_w = {a} mm, not the required --aw {x}: give one of them (for a_w = {x2} mm the shift sum must "
     "be x1 + x2 = {xs})",
     "--shift {s} даёт a_w = {a} мм, а не заданное --aw {x}: задайте что-то одно (для a_w = {x2} мм сумма смещений "
     "должна быть x1 + x2 = {xs})"),
    ("--{o} is {v} m, over the limit of {m} m; give metres (e.g. 0.1 for a 100 mm crank)",
     "--{o} = {v} м — больше предела {m} м; задайте длины в метрах (например, 0.1 для кривошипа 100 мм)"),
    # gears/aa_bar.py: tmm planetary
    ("cannot read {w} = {t}: write it as a positive fraction, e.g. {e}",
     "не удалось прочитать {w} = {t}: запишите положительную дробь, например {e}"),
    ("{w} = {t} must be a positive fraction, e.g. {e}", "{w} = {t} должно быть положительной дробью, например {e}"),
    ("the ratio i = {i} must be a positive fraction, e.g. --ratio 1/10",
     "передаточное отношение i = {i} должно быть положительной дробью, например --ratio 1/10"),
    ("the ratio i = {i} of the AA̅ mechanism must be less than 1 (i = 1 − Z4/Z1 with Z4 > 0); e.g. --ratio 1/10",
     "передаточное отношение механизма AA̅ i = {i} должно быть меньше 1 (i = 1 − Z4/Z1 при Z4 > 0); например "
     "--ratio 1/10"),
    ("module must be a positive number of mm, got {x}; e.g. --module 5",
     "модуль должен быть положительным числом мм, задано {x}; например --module 5"),
    ("tooth limits {lo} … {hi} are empty; give 1 ≤ --z-min ≤ --z-max, e.g. --z-min 18 --z-max 180",
     "пределы чисел зубьев {lo} … {hi} пусты; задайте 1 ≤ --z-min ≤ --z-max, например --z-min 18 --z-max 180"),
    ("C = {c} is outside its feasible range for i = {i}: 1 < C < 1/(1 − i) = {hi} ≈ {h} (else Z2 ≤ 0); choose C "
     "inside it, e.g. --c {e}",
     "C = {c} вне области существования для i = {i}: 1 < C < 1/(1 − i) = {hi} ≈ {h} (иначе Z2 ≤ 0); выберите C "
     "внутри неё, например --c {e}"),
    ("C = {c} = {x} is outside its feasible range for i = {i}: 1 < C < 1/(1 − i) = {hi} ≈ {h} (else Z2 ≤ 0); choose C "
     "inside it, e.g. --c {e}",
     "C = {c} = {x} вне области существования для i = {i}: 1 < C < 1/(1 − i) = {hi} ≈ {h} (иначе Z2 ≤ 0); выберите C "
     "внутри неё, например --c {e}"),
    ("no tooth set within {lo} … {hi} teeth: the smallest for i = {i}, C = {c}, k = {k} is Z = {z} (Z1 a multiple of "
     "{s}); widen --z-min/--z-max or choose a simpler C",
     "нет набора чисел зубьев в пределах {lo} … {hi}: наименьший для i = {i}, C = {c}, k = {k} — Z = {z} (Z1 кратно "
     "{s}); расширьте --z-min/--z-max или выберите более простое C"),
    ("--family {n} is not within the tooth limits {lo} … {hi}; the family is {f}",
     "--family {n} не укладывается в пределы чисел зубьев {lo} … {hi}; возможны кратности {f}"),
    ("the centre distance a_w = {a} mm of the first pair is too small for Z3 + Z4 = {z}; increase x1 + x2",
     "межосевое расстояние первой пары a_w = {a} мм мало для Z3 + Z4 = {z}; увеличьте x1 + x2"),
    ("the shifts make gear {n} (Z = {z}, x = {x}) pointed: its tip thickness would be s_a = {s} mm ≤ 0; {rest}",
     "при этих смещениях зуб колеса {n} (Z = {z}, x = {x}) заострён: толщина зуба по окружности вершин "
     "s_a = {s} мм ≤ 0; {rest}"),
    ("a larger planet shift --x2 leaves less of x_Σ34 = {x} to wheel 4, a negative first pair (x1 + x2 < 0) lowers "
     "α_w34, or choose a smaller C",
     "больший коэффициент смещения сателлита --x2 оставит колесу 4 меньшую часть x_Σ34 = {x}, отрицательная сумма "
     "смещений первой пары (x1 + x2 < 0) уменьшит α_w34; или выберите меньшее C"),
    ("choose a smaller shift for it", "уменьшите его коэффициент смещения"),
    # linkage/inputs.py: the --input TOML
    ("{w}: unknown key '{k}'; known keys: {ks}", "{w}: неизвестный ключ '{k}'; допустимые ключи: {ks}"),
    ("{w}: '{k}' must be a number, e.g. {k2} = 0.1 (metres, with a decimal dot)",
     "{w}: '{k}' должно быть числом, например {k2} = 0.1 (в метрах, с десятичной точкой)"),
    ("{w}: 'positions' must be a whole number, e.g. positions = 12",
     "{w}: 'positions' должно быть целым числом, например positions = 12"),
    ("{p} is larger than 64 KiB; it should hold only the mechanism's dimensions",
     "{p} больше 64 КиБ; в нём должны быть только размеры механизма"),
    ("{p} does not exist; give the TOML file with the mechanism's dimensions",
     "{p} не существует; укажите файл TOML с размерами механизма"),
    ("{p} is a folder; give a TOML file", "{p} — папка; укажите файл TOML"),
    ("{p} is not valid TOML ({why}); write lines like r1 = 0.10 (a decimal dot)",
     "{p} — не TOML ({why}); пишите строки вида r1 = 0.10 (с десятичной точкой)"),
    ("{p} has no [variants.N] tables; drop --variant or add the tables",
     "в {p} нет таблиц [variants.N]; уберите --variant или добавьте таблицы"),
    ("{p}: 'variants' must be tables such as [variants.1]", "{p}: 'variants' должны быть таблицами вида [variants.1]"),
    ("{p} has {n} variants; at most {m} are read", "в {p} {n} вариантов; читается не более {m}"),
    ("{p} is a table of variants ({names}); choose one with --variant N",
     "{p} — таблица вариантов ({names}); выберите один: --variant N"),
    ("{p} has no variant {v}; it has: {names}", "в {p} нет варианта {v}; есть: {names}"),
    # commands/linkage.py and linkage/geometry.py
    ("--variant needs --input FILE with [variants.N] tables", "--variant требует --input ФАЙЛ с таблицами [variants.N]"),
    ("give {opts} (metres; or put them in --input FILE)", "задайте {opts} (в метрах; или запишите их в --input ФАЙЛ)"),
    ("give the crank speed once: --rpm N or --omega RAD_S, not both",
     "задайте скорость кривошипа один раз: --rpm N или --omega RAD_S, но не оба"),
    ("give the crank speed: --rpm N (or --omega RAD_S)", "задайте скорость кривошипа: --rpm N (или --omega RAD_S)"),
    ("{w} is {v}; give a positive crank speed (φ21 grows with time)",
     "{w} = {v}; задайте положительную скорость кривошипа (φ21 растёт со временем)"),
    ("{w} is {v}; give a number in metres", "{w} = {v}; задайте число в метрах"),
    ("{w} is {v}; give a finite number in metres", "{w} = {v}; задайте конечное число в метрах"),
    ("--{n} is {v} m; lengths must be positive (the crank O21A)",
     "--{n} = {v} м; длины должны быть положительными (кривошип O21A)"),
    ("--{n} is {v} m; lengths must be positive (the link's pivot O41 lies h below the crank centre)",
     "--{n} = {v} м; длины должны быть положительными (ось кулисы O41 лежит на h ниже центра кривошипа)"),
    ("--{n} is {v} m; lengths must be positive (the link's arm O41B)",
     "--{n} = {v} м; длины должны быть положительными (плечо кулисы O41B)"),
    ("--{n} is {v} m; lengths must be positive (the rod BC)",
     "--{n} = {v} м; длины должны быть положительными (шатун BC)"),
    ("--{n} is {v} m; lengths must be positive ({what})", "--{n} = {v} м; длины должны быть положительными ({what})"),
    ("the crank circle passes through the link's pivot O41 (√(c² + h²) = r1 = {r} m): the block would run into the "
     "pivot and the link's angle is undefined; change --h or --c",
     "окружность кривошипа проходит через ось кулисы O41 (√(c² + h²) = r1 = {r} м): камень упрётся в ось, и угол "
     "кулисы не определён; измените --h или --c"),
    ("the block leaves the slotted link: it reaches {x} m from O41 (√(c² + h²) + r1) but the link O41B is only r2 = {r} "
     "m long; make --r2 at least {x2} m or shorten --r1",
     "камень сходит с кулисы: он удаляется на {x} м от O41 (√(c² + h²) + r1), а кулиса O41B длиной лишь r2 = {r} м; "
     "задайте --r2 не меньше {x2} м или уменьшите --r1"),
    ("the rod cannot reach the ram's guide: B comes {x} m from the line y = b = {b} m but the rod BC is r3 = {r} m; "
     "make --r3 longer than {x2} m or move the guide (--b)",
     "шатун не достаёт до направляющей ползуна: точка B отходит на {x} м от прямой y = b = {b} м, а шатун BC "
     "длиной r3 = {r} м; задайте --r3 больше {x2} м или сместите направляющую (--b)"),
    # render/note: the explanatory note
    ("note template {p} does not exist; give a typst file (start from tmm's note-style.typ, see docs/note.md)",
     "файл стиля записки {p} не существует; укажите файл typst (за основу возьмите note-style.typ из tmm, см. "
     "docs/note.md)"),
    ("note template {p} is larger than 1 MiB; it should hold only the note's style",
     "файл стиля записки {p} больше 1 МиБ; в нём должен быть только стиль записки"),
    ("note template {p} is not UTF-8 text; save it as UTF-8", "файл стиля записки {p} — не текст в UTF-8; сохраните его в UTF-8"),
    ("cannot read note template {p} ({why})", "не удалось прочитать файл стиля записки {p} ({why})"),
    ("the typst package is missing; reinstall tmm (pip install tmm) to write the note",
     "нет пакета typst; переустановите tmm (pip install tmm), чтобы получить записку"),
    ("the note could not be typeset ({why}); check the note template or {src}",
     "записку не удалось сверстать ({why}); проверьте файл стиля записки или {src}"),
    ("no {src} here; run tmm note in the folder of the note (or give the .typ file)",
     "здесь нет {src}; запустите tmm note в папке записки (или укажите файл .typ)"),
    ("{src} is not a typst file (.typ)", "{src} — не файл typst (.typ)"),
    ("cannot write {p} ({why})", "не удалось записать {p} ({why})"),
    # tmm linkage MECH.toml (issue 24): inputs/mechanism.py, linkage/mechanism_file.py, assembly.py, sheet1.py
    ("{p} is a mechanism file; run tmm linkage {p} (without --input)",
     "{p} — файл механизма; запустите tmm linkage {p} (без --input)"),
    ("the A1 sheet 1 needs a mechanism file: tmm linkage MECH.toml --sheets (the Whitworth mechanism is "
     "docs/examples/whitworth.toml)",
     "для листа 1 формата A1 нужен файл механизма: tmm linkage MECH.toml --sheets (механизм Витворта — "
     "docs/examples/whitworth.toml)"),
    ("{p} is larger than 256 KiB; a mechanism file holds a few tables",
     "{p} больше 256 КиБ; в файле механизма всего несколько таблиц"),
    ("{p} does not exist; give the mechanism's TOML file (see docs/mechanism.md)",
     "{p} не существует; укажите файл TOML с описанием механизма (см. docs/mechanism.md)"),
    ("{p} is not valid TOML ({why}); see docs/mechanism.md for the form",
     "{p} — не TOML ({why}); форма файла описана в docs/mechanism.md"),
    ("cannot read {p} ({why})", "не удалось прочитать {p} ({why})"),
    ("{f} describes the mechanism; drop {opts} (the options of the Whitworth mechanism)",
     "{f} уже описывает механизм; уберите {opts} (параметры механизма Витворта)"),
    ("--plan needs a mechanism file (tmm linkage MECH.toml --plan N); for the Whitworth options use --at DEG",
     "--plan требует файла механизма (tmm linkage MECH.toml --plan N); для механизма Витворта задайте --at ГРАД"),
    ("--positions is {n}; give a whole number of crank positions from 2 to 360 (the book uses 12)",
     "--positions = {n}; задайте целое число положений кривошипа от 2 до 360 (в пособиях 12)"),
    ("--plan {p}: there is no such position; the positions are {ls}",
     "--plan {p}: такого положения нет; есть положения {ls}"),
    ("{src}: the file must hold TOML tables", "{src}: файл должен содержать таблицы TOML"),
    ("{src}: '{k}' is read as '{kk}': a top-level key must come before the first [table] of the file",
     "{src}: '{k}' прочитан как '{kk}': ключи верхнего уровня пишутся до первой [таблицы] файла"),
    ("{src}: unknown key '{k}'; known keys here: {ks}", "{src}: неизвестный ключ '{k}'; допустимые здесь ключи: {ks}"),
    ("{src}: '{k}' must be a table, e.g. [{t}]", "{src}: '{k}' должно быть таблицей, например [{t}]"),
    ("{src}: '{k}' must be a table [[group]]", "{src}: '{k}' должно быть таблицей [[group]]"),
    ("{src}: 'point' must be tables [[point]]", "{src}: 'point' должны быть таблицами [[point]]"),
    ("{src}: '[frame]' must be a table of fixed joints, e.g. {ex}",
     "{src}: '[frame]' должно быть таблицей неподвижных шарниров, например {ex}"),
    ("{src}: '{k}' must be a number, e.g. {ex}", "{src}: '{k}' должно быть числом, например {ex}"),
    ("{src}: '{k}' is {v}; give a finite number, e.g. {ex}", "{src}: '{k}' = {v}; задайте конечное число, например {ex}"),
    ("{src}: '{k}' is {v}; a length must lie in (0, {m}] m", "{src}: '{k}' = {v}; длина должна лежать в (0, {m}] м"),
    ("{src}: '{k}' is {v}; a coordinate must lie in [−{m}, {m2}] m",
     "{src}: '{k}' = {v}; координата должна лежать в [−{m}, {m2}] м"),
    ("{src}: '{k}' must be a list of two numbers [x, y] in metres, e.g. {ex}",
     "{src}: '{k}' должно быть списком из двух чисел [x, y] в метрах, например {ex}"),
    ("{src}: '{k}' must be a list of two lengths [AB, BC] in metres, e.g. {ex}",
     "{src}: '{k}' должно быть списком из двух длин [AB, BC] в метрах, например {ex}"),
    ("{src}: '{k}' must be a list of {n} joint names, e.g. {ex}",
     "{src}: '{k}' должно быть списком из {n} имён шарниров, например {ex}"),
    ("{src}: '{k}' names a joint twice ({js})", "{src}: в '{k}' шарнир назван дважды ({js})"),
    ("{src}: '{k}' must be text in quotes, e.g. {ex}", "{src}: '{k}' должно быть текстом в кавычках, например {ex}"),
    ("{src}: '{k}' is {v}; choose one of {cs}", "{src}: '{k}' = {v}; допустимо одно из: {cs}"),
    ("{src}: '{k}' is {v}; a name is a letter followed by letters, digits or _ (at most {n}), e.g. \"B\" or \"O1\"",
     "{src}: '{k}' = {v}; имя — буква, за которой идут буквы, цифры или _ (не более {n}), например \"B\" или "
     "\"O1\""),
    ("{src}: 'crank.rpm' is missing, e.g. rpm = 1500 (or omega in rad/s)",
     "{src}: нет ключа 'crank.rpm', например rpm = 1500 (или omega в рад/с)"),
    ("{src}: '{k}' is missing, e.g. {ex}", "{src}: нет ключа '{k}', например {ex}"),
    ("{src}: '{k}': the name {n} is taken; give each joint, point and link its own name",
     "{src}: '{k}': имя {n} уже занято; дайте каждому шарниру, точке и звену своё имя"),
    ("{src}: '{k}': the joint {n} already carries a slider or a block; give each joint, point and link its own name",
     "{src}: '{k}': на шарнире {n} уже есть ползун или камень; дайте каждому шарниру, точке и звену своё имя"),
    ("{src}: '{k}': joint {n} is the [[point]] of the link {l}, which is not placed before this group",
     "{src}: '{k}': шарнир {n} — точка [[point]] звена {l}, которое не построено до этой группы"),
    ("{src}: '{k}': joint {n} is not placed before this group; define it in [frame], as the crank's joint, in an "
     "earlier group or as a [[point]] of an earlier link",
     "{src}: '{k}': шарнир {n} не построен до этой группы; задайте его в [frame], как шарнир кривошипа, в одной из "
     "предыдущих групп или как точку [[point]] построенного ранее звена"),
    ("{src}: '{k}' is {v}, not a joint of [frame]; the crank turns about a fixed joint",
     "{src}: '{k}' = {v} — не шарнир стойки [frame]; кривошип вращается вокруг неподвижного шарнира"),
    ("{src}: give the crank's speed once: 'crank.rpm' or 'crank.omega', not both",
     "{src}: задайте скорость кривошипа один раз: 'crank.rpm' или 'crank.omega', но не оба"),
    ("{src}: '{k}' is {v}; the mean speed must lie in (0, {m}] rpm (the sense is 'crank.sense')",
     "{src}: '{k}' = {v}; средняя частота вращения должна лежать в (0, {m}] об/мин (направление — 'crank.sense')"),
    ("{src}: '{k}' is {v}; the mean speed must lie in (0, {m}] rad/s (the sense is 'crank.sense')",
     "{src}: '{k}' = {v}; средняя угловая скорость должна лежать в (0, {m}] рад/с (направление — 'crank.sense')"),
    ("{src}: '{k}' is {v}; the kinds are RRR, RRP and RPR (class II groups of kinds 1–3)",
     "{src}: '{k}' = {v}; допустимые виды групп: RRR, RRP и RPR (группы II класса 1–3-го вида)"),
    ("{src}: '{k}' is {v}; give a whole number of crank positions from 2 to 360, e.g. positions = 12",
     "{src}: '{k}' = {v}; задайте целое число положений кривошипа от 2 до 360, например positions = 12"),
    ("{src}: '{k}' has {n} entries; at most {m} are read", "{src}: в '{k}' записей: {n}; читается не более {m}"),
    ("{src}: the mechanism has no [[group]]; add the class II groups in the order of the structural formula",
     "{src}: в механизме нет групп [[group]]; добавьте группы II класса в порядке формулы строения"),
    ("{src}: group {n} ({l}) hangs on fixed joints only ({js}); it would not move: hang it on the crank or a moving "
     "link",
     "{src}: группа {n} ({l}) присоединена только к неподвижным шарнирам ({js}) и не будет двигаться: присоедините "
     "её к кривошипу или подвижному звену"),
    ("{src}: '{k}': measure a point of the slotted link {l} from its pivot {c}: link = [\"{c}\", \"{a}\"]",
     "{src}: '{k}': точку кулисы {l} отсчитывайте от её оси {c}: link = [\"{c}\", \"{a}\"]"),
    ("{src}: '{k}': no moving link joins {a} and {b}; name a link by two of its joints, e.g. [\"A\", \"B\"]",
     "{src}: '{k}': ни одно подвижное звено не соединяет {a} и {b}; задайте звено двумя его шарнирами, например "
     "[\"A\", \"B\"]"),
    ("{src}: 'output' is {v}; give a slider's joint (e.g. \"B\") or a moving link by two joints (e.g. [\"C\", \"B\"])",
     "{src}: 'output' = {v}; задайте шарнир ползуна (например \"B\") или подвижное звено двумя шарнирами "
     "(например [\"C\", \"B\"])"),
    ("{src}: 'plan' is {v}; give the label of a position, e.g. plan = 3",
     "{src}: 'plan' = {v}; задайте обозначение положения, например plan = 3"),
    ("{src}: group {n} ({l}) cannot be assembled at φ = {phi}°: |{ac}| = {d} m but {ab} + {bc} = {s} m; make {ab} + "
     "{bc} longer than {d} m",
     "{src}: группу {n} ({l}) нельзя собрать при φ = {phi}°: |{ac}| = {d} м, а {ab} + {bc} = {s} м; сделайте "
     "{ab} + {bc} длиннее {d} м"),
    ("{src}: group {n} ({l}) cannot be assembled at φ = {phi}°: |{ac}| = {d} m but |{ab} − {bc}| = {diff} m; {short} "
     "is too short beside {long}: make it longer than {x} m",
     "{src}: группу {n} ({l}) нельзя собрать при φ = {phi}°: |{ac}| = {d} м, а |{ab} − {bc}| = {diff} м; звено "
     "{short} слишком короткое рядом с {long}: сделайте его длиннее {x} м"),
    ("{src}: group {n} ({l}) cannot be assembled at φ = {phi}°: {a} comes {h} m from the guide of {b} but {ab} = {len} "
     "m; make {ab} longer than {h} m",
     "{src}: группу {n} ({l}) нельзя собрать при φ = {phi}°: точка {a} отходит на {h} м от направляющей {b}, а "
     "{ab} = {len} м; сделайте {ab} длиннее {h} м"),
    ("{src}: group {n} ({l}) cannot be assembled at φ = {phi}°: the block's joint {a} passes through the pivot {c} of "
     "the slotted link (its angle is undefined); move {c} off the path of {a}",
     "{src}: группу {n} ({l}) нельзя собрать при φ = {phi}°: шарнир камня {a} проходит через ось {c} кулисы (её угол "
     "не определён); сместите {c} с траектории точки {a}"),
]


def _template_pattern(template: str) -> str:
    """An English message template ("{what} is {x}; give …") as a regular expression with named
    groups; a field named twice matches the same text again.

    >>> _template_pattern("{w}:{x}/{x}")
    '(?P<w>.*?):(?P<x>.*?)/(?P=x)'
    """
    out, seen = [], set()
    for literal, field in re.findall(r"([^{]*)(?:\{(\w+)\})?", template):
        out.append(re.escape(literal))
        if field:
            out.append(f"(?P={field})" if field in seen else f"(?P<{field}>.*?)")
            seen.add(field)
    return "".join(out)


ERRORS += [(_template_pattern(en), ru) for en, ru in TEMPLATES]


@cache
def _errors() -> list:
    """ERRORS compiled, on the first error (compiling them all costs ~50 ms: not for `--help`)."""
    return [(re.compile(p + r"\Z", re.S), t) for p, t in ERRORS]


_CLICK_INVALID = re.compile(r"(Недопустимое значение(?: [^:]*)?: )(.*)\Z", re.S)  # click's frame, ours inside


METAVARS = {"[OPTIONS]": "[ПАРАМЕТРЫ]", "COMMAND [ARGS]...": "КОМАНДА [АРГУМЕНТЫ]...",
            "[COMMAND] [ARGS]...": "[КОМАНДА] [АРГУМЕНТЫ]...",
            "COMMAND1 [ARGS]... [COMMAND2 [ARGS]...]...": "КОМАНДА1 [АРГУМЕНТЫ]... [КОМАНДА2 [АРГУМЕНТЫ]...]..."}
WORDS = {"error": "ошибка", "internal error": "внутренняя ошибка", "aborted": "прервано",
         "interrupted": "прервано пользователем", "run with TMM_DEBUG=1 for details": "подробности: TMM_DEBUG=1"}


_PLACES = [(re.compile(p), ru) for p, ru in (
    (r"^answers file ", "файл результатов "), (r"^roster ", "список группы "), (r"^variants file ", "файл заданий "),
    (r"(\S) line (\d+)", r"\1, строка \2"),  # "table.csv line 3" → "table.csv, строка 3"
    (r" \(variant (\d+)\)", r" (вариант \1)"), (r"^the ratio i$", "передаточное отношение i"),
    (r"^note template ", "файл стиля записки "),
    # the system's reasons (OSError.strerror) in parentheses
    (r"^Permission denied$", "нет прав доступа"), (r"^No such file or directory$", "нет такого файла или папки"),
    (r"^Read-only file system$", "файловая система только для чтения"), (r"^No space left on device$", "нет места на диске"),
    (r"^Is a directory$", "это папка"), (r"^Not a directory$", "это не папка"),
    (r"^Disk quota exceeded$", "превышена дисковая квота"), (r"^File name too long$", "слишком длинное имя файла"),
)]


def _place(text: str) -> str:
    """The place named in a message (a file, its line, a variant) in Russian."""
    for pattern, ru in _PLACES:
        text = pattern.sub(ru, text)
    return text


def translate_error(message: str) -> str:
    """Our English error sentence in Russian, if the catalogue knows it (else unchanged).

    >>> translate_error("variant 99 is not in the table; choose a variant from 1 to 68")
    'варианта 99 нет в таблице; выберите вариант от 1 до 68'
    >>> translate_error("Недопустимое значение '--jobs': 0 is out of range; give a whole number from 1 to 64 (docs/limits.md)")
    "Недопустимое значение '--jobs': 0 вне допустимого диапазона; задайте целое число от 1 до 64 (docs/limits.md)"
    """
    text = " ".join(str(message).split())
    for pattern, template in _errors():
        m = pattern.match(text)
        if m:  # "table.csv line 3" inside a quoted place → "table.csv, строка 3"
            parts = {k: _place(v or "") for k, v in m.groupdict().items()}
            if "rest" in parts:  # a message inside a message ("roster line 3: <the row's error>")
                parts["rest"] = translate_error(parts["rest"])
            return template.format(**parts)
    m = _CLICK_INVALID.match(text)  # "Недопустимое значение '--crank-rpm': -5 is out of range; …" (limits.Range)
    if m and translate_error(m.group(2)) != m.group(2):
        return m.group(1) + translate_error(m.group(2))
    return text


def error_text(message: str, lang: str) -> str:
    """An error shown inside a table (a roster row's, a student's) in the output language."""
    return translate_error(message) if lang == "ru" else message


class _DefaultRu(str):
    """"по умолчанию: {default}" whose number takes a decimal comma (click formats the default as
    ``str(5.0)``): ``[по умолчанию: 5,0]``."""

    def format(self, *args, **kwargs):
        import re

        kwargs = {k: re.sub(r"(?<=\d)\.(?=\d)", ",", v) if isinstance(v, str) else v for k, v in kwargs.items()}
        return str.format(self, *args, **kwargs)


def _gettext(message: str) -> str:
    text = CLICK.get(message, message)
    return _DefaultRu(text) if message == "default: {default}" else text


def _ngettext(singular: str, plural: str, n: int) -> str:
    forms = CLICK_PLURAL.get(singular)
    if forms is None:
        return singular if n == 1 else plural
    return forms[0] if n == 1 else forms[1]


def _version_ru(ctx, param, value):
    """`tmm --version` in Russian (click's message is fixed when the option is declared)."""
    if not value or ctx.resilient_parsing:
        return
    from importlib.metadata import version

    import click

    click.echo(f"tmm, версия {version('tmm')}")
    ctx.exit()


def _commands(cmd, path: str):
    yield path, cmd
    for name, sub in getattr(cmd, "commands", {}).items():
        yield from _commands(sub, f"{path} {name}")


@contextmanager
def russian(cli):
    """Within the block, `cli`'s help texts and click's messages are Russian; afterwards English
    again (tests run many commands in one process)."""
    import click.core
    import click.decorators
    import click.exceptions
    import click.formatting
    import click.parser
    import click.types
    import click.utils

    saved_help: list[tuple[object, str, object]] = []
    for path, cmd in _commands(cli, "tmm"):
        if path in COMMANDS:
            saved_help.append((cmd, "help", cmd.help))
            saved_help.append((cmd, "short_help", cmd.short_help))
            cmd.help, cmd.short_help = COMMANDS[path], None
        for attr, ru in (("options_metavar", METAVARS), ("subcommand_metavar", METAVARS)):
            value = getattr(cmd, attr, None)
            if value in ru:
                saved_help.append((cmd, attr, value))
                setattr(cmd, attr, ru[value])
        # click caches the -h/--help option of a command: never let a Russian one outlive the block
        cached = getattr(cmd, "_help_option", None)
        saved_help.append((cmd, "_help_option", cached))
        if cached is not None and cached.help in OPTIONS:
            saved_help.append((cached, "help", cached.help))
            cached.help = OPTIONS[cached.help]
        for param in cmd.params:
            if param.name == "version" and getattr(param, "is_flag", False):
                saved_help.append((param, "callback", param.callback))
                param.callback = _version_ru
            text = getattr(param, "help", None)
            if text in OPTIONS:
                saved_help.append((param, "help", text))
                param.help = OPTIONS[text]
    modules = (click.core, click.decorators, click.exceptions, click.formatting, click.parser, click.types,
               click.utils)
    saved_fn = [(m, name, getattr(m, name)) for m in modules for name in ("_", "ngettext") if hasattr(m, name)]
    for m, name, _fn in saved_fn:
        setattr(m, name, _gettext if name == "_" else _ngettext)
    try:
        yield
    finally:
        for m, name, fn in saved_fn:
            setattr(m, name, fn)
        for obj, attr, value in reversed(saved_help):
            setattr(obj, attr, value)
