"""A synthesised mechanism as a mechanism file (docs/mechanism.md) — the text `tmm synth` writes
and `tmm linkage` reads — and the check of it by `tmm linkage`'s own core.

The file is complete: the frame, the crank, the groups, the task's optional speed, sense, start,
positions, points, masses, load and dynamics, and a ``[synthesis]`` table that records the task, so
the note can tell that the mechanism came from synthesis. Joint names follow the book's letters:
crank-slider O, A, B; crank-rocker A, B, C, D; slotted-link O1, A, O2, B, C.
"""

from __future__ import annotations

import json
import math
import tomllib

from ..notes import Note
from ..records import record
from .synthesis import RockerSynthesis, SliderSynthesis, SlottedSynthesis, crank_rocker

DEFAULT_RPM = 60.0  # when the task gives no speed (the kinematics' shape does not depend on it)
TASK_TABLES = ("point", "mass", "load", "dynamics")  # copied as they stand in the task


def _value(v) -> str:
    """One TOML value (str, bool, int, float, list, table as an inline table)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if v != v else ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    return json.dumps(str(v), ensure_ascii=False)


def _key(k: str) -> str:
    return k if k and all(c.isalnum() and c.isascii() or c in "_-" for c in k) else json.dumps(k, ensure_ascii=False)


def _table(name: str, t: dict, array: bool = False) -> list[str]:
    lines = [f"[[{name}]]" if array else f"[{name}]"]
    lines += [f"{_key(k)} = {_value(v)}" for k, v in t.items()]
    return lines


def _mm(x: float) -> str:
    return f"{x * 1000:.3f} mm"


def _frame_crank(frame: dict, pivot: str, length: float, task) -> list[str]:
    lines = ["", "[frame]"] + [f"{k} = [{x!r}, {y!r}]" for k, (x, y) in frame.items()]
    lines += ["", "[crank]", f'pivot = "{pivot}"', 'joint = "A"' if pivot != "A" else 'joint = "B"',
              f"length = {length!r}   # {_mm(length)}"]
    if task.omega is not None:
        lines.append(f"omega = {task.omega!r}")
    else:
        lines.append(f"rpm = {task.rpm if task.rpm is not None else DEFAULT_RPM!r}")
    lines.append(f'sense = "{task.sense}"')
    if task.start_deg is not None:
        lines.append(f"start_deg = {task.start_deg!r}")
    return lines


def _fix(x: float) -> float:
    return 0.0 if abs(x) < 1e-15 else float(x)


def mechanism_toml(syn, task, mirror: bool = False, default_name: str = "") -> str:
    """The mechanism file's text for the synthesis `syn` of `task` (:class:`.synthesis_task.Task`).
    `mirror` reflects the mechanism (about the frame line, or the vertical through O1), which swaps
    the slow and the fast stroke for the same sense of rotation; `default_name` names it when the
    task does not (the command gives the type's name in the reader's language)."""
    head = [f"# {task.name}" if task.name else "# A mechanism found by tmm synth",
            "# Written by `tmm synth` from the task recorded in [synthesis] below (docs/synthesis.md);",
            "# `tmm linkage` reads it as any mechanism file (docs/mechanism.md).",
            f"name = {_value(task.name or default_name)}",
            f"positions = {task.positions}"]
    if task.gravity is not None:
        head.append(f"gravity = {_value(task.gravity)}")
    if task.plan is not None:
        head.append(f"plan = {_value(task.plan)}")
    if isinstance(syn, SliderSynthesis):
        y = syn.offset if mirror else -syn.offset
        body = _frame_crank({"O": (0.0, 0.0)}, "O", syn.crank, task)
        body += ["", "[[group]]                    # the rod AB and the slider B", 'kind = "RRP"', 'joints = ["A", "B"]',
                 f"length = {syn.rod!r}   # {_mm(syn.rod)}",
                 f"guide = {{ through = [0.0, {_fix(y)!r}], angle_deg = 0.0 }}   # the offset e = {_mm(syn.offset)}",
                 'branch = "ahead"']
    elif isinstance(syn, RockerSynthesis):
        d = syn.D
        branch = syn.branch * (-1 if mirror else 1)
        body = _frame_crank({"A": (0.0, 0.0), "D": (_fix(d.real), 0.0)}, "A", syn.crank, task)
        body += ["", "[[group]]                    # the coupler BC and the rocker CD", 'kind = "RRR"',
                 'joints = ["B", "C", "D"]',
                 f"lengths = [{syn.coupler!r}, {syn.rocker!r}]   # {_mm(syn.coupler)}, {_mm(syn.rocker)}",
                 f'branch = "{"left" if branch > 0 else "right"}"']
    elif isinstance(syn, SlottedSynthesis):
        body = _frame_crank({"O1": (0.0, 0.0), "O2": (0.0, _fix(-syn.frame))}, "O1", syn.crank, task)
        body += ["", "[[group]]                    # the block on A and the slotted link O2B", 'kind = "RPR"',
                 'joints = ["A", "O2"]', "", "[[point]]                    # where the rod hangs", 'name = "B"',
                 'link = ["O2", "A"]', f"along = {syn.link!r}   # {_mm(syn.link)}"]
        body += ["", "[[group]]                    # the rod BC and the ram C", 'kind = "RRP"', 'joints = ["B", "C"]',
                 f"length = {syn.rod!r}   # {_mm(syn.rod)}",
                 f"guide = {{ through = [0.0, {_fix(syn.guide - syn.frame)!r}], angle_deg = 0.0 }}   # the middle of "
                 "the sagitta", f'branch = "{"ahead" if mirror else "behind"}"']
    else:  # pragma: no cover
        raise TypeError(type(syn))
    tables = []
    for name in TASK_TABLES:
        value = task.tables.get(name)
        if value is None:
            continue
        if isinstance(value, list):
            for t in value:
                tables += [""] + _table(name, t, array=True)
        else:
            tables += [""] + _table(name, value)
    record_lines = ["", "[synthesis]                  # the task (tmm synth)"]
    record_lines += [f"{_key(k)} = {_value(v)}" for k, v in task.record.items()]
    return "\n".join(head + body + tables + record_lines) + "\n"


@record
class Check:
    """`tmm linkage`'s own numbers of the mechanism written, beside the task's."""

    stroke: float | None  # H [m] (a slider's output)
    swing: float | None  # ψ [rad] (a rocker's output)
    time_ratio: float | None  # K
    gamma_min: float  # 90° − the worst pressure angle over the groups [rad]


def check_text(text: str, source: str = "synthesis"):
    """Parse the mechanism file's text as `tmm linkage` does and analyse its cycle: (Mechanism, Cycle, Check)."""
    from .mechanism_file import parse_mechanism
    from .positions import cycle

    from .sheet2_file import parse_sheet2

    mech = parse_mechanism(tomllib.loads(text), source)
    parse_sheet2(mech, source)  # the task's masses and load, as tmm linkage will check them
    c = cycle(mech, source)
    worst = max(p.worst for p in c.pressure)
    slider = mech.output.kind == "slider"
    return mech, c, Check(c.stroke if slider else None, None if slider else c.stroke, c.time_ratio,
                          math.pi / 2.0 - worst)


@record(eq=False)
class Synthesised:
    """What `tmm synth` hands to its renderers: the task, the synthesis, the file and its check."""

    task: object  # synthesis_task.Task
    synthesis: object  # SliderSynthesis | RockerSynthesis | SlottedSynthesis
    text: str  # the mechanism file
    mechanism: object  # linkage.mechanism.Mechanism, as tmm linkage parses the text
    cycle: object  # linkage.positions.Cycle
    check: Check
    mirrored: bool
    notes: tuple


LOW_TRANSMISSION_DEG = 40.0  # the usual smallest transmission angle of a lever mechanism
PRESSURE_LIMIT_DEG = 45.0  # the usual largest pressure angle on a slider
PRESSURE_WARN_DEG = 40.0  # a crank-slider is warned of from here (near the limit) …
LAMBDA_WARN = 0.4  # … or from this λ = l_OA/l_AB (usual 0.2 … 0.35; at 0.5 the rod is twice the crank)


def _notes(task, syn, chk: Check, mirrored: bool) -> tuple[Note, ...]:
    notes = []
    if isinstance(syn, RockerSynthesis):
        gamma = math.degrees(syn.gamma_min)
        if syn.mode == "transmission":
            notes.append(Note.make("synth_best_pivot", "assumption", gamma_deg=gamma))
        else:
            notes.append(Note.make("synth_frame_pivot", "assumption", frame_mm=syn.frame * 1000, gamma_deg=gamma,
                                   best_deg=math.degrees(syn.gamma_best)))
        if gamma < LOW_TRANSMISSION_DEG and syn.gamma_task is None:
            if syn.mode == "frame":  # the advice the file can take: another frame, or no frame and a γ
                best = crank_rocker(syn.rocker, syn.swing, syn.time_ratio)
                notes.append(Note.make("synth_low_transmission_frame", "warning", gamma_deg=gamma,
                                       limit_deg=LOW_TRANSMISSION_DEG, frame_toml=f"frame = {best.frame:.4g}",
                                       best_deg=math.degrees(best.gamma_min)))
            else:
                notes.append(Note.make("synth_low_transmission", "warning", gamma_deg=gamma,
                                       limit_deg=LOW_TRANSMISSION_DEG))
    if isinstance(syn, SliderSynthesis):
        alpha = 90.0 - math.degrees(chk.gamma_min)  # the largest pressure angle on the slider, tmm linkage's
        if alpha >= PRESSURE_WARN_DEG or syn.lam >= LAMBDA_WARN:
            notes.append(Note.make("synth_slider_pressure", "warning", alpha_deg=alpha, lam=syn.lam,
                                   limit_deg=PRESSURE_LIMIT_DEG))
    if isinstance(syn, SlottedSynthesis):
        if "rod_ratio" not in task.values:
            notes.append(Note.make("synth_rod_ratio", "assumption", ratio=syn.rod_ratio))
        if syn.slot > syn.link:
            notes.append(Note.make("synth_slot", "warning", slot_mm=syn.slot * 1000, link_mm=syn.link * 1000))
    if task.rpm is None and task.omega is None:
        notes.append(Note.make("synth_default_rpm", "assumption", rpm=DEFAULT_RPM))
    if mirrored:
        notes.append(Note.make("synth_mirror", "assumption"))
    if chk.time_ratio is not None and chk.time_ratio < 1.0 - 1e-9:
        notes.append(Note.make("synth_fast_working", "warning", time_ratio=chk.time_ratio))
    return tuple(notes)


def synthesised_file(syn, task, source: str = "synthesis", default_name: str = "") -> Synthesised:
    """The mechanism file's text and its check. The working stroke must be the slower one (K ≥ 1
    as `tmm linkage` counts it): when the task's load.working makes it the faster, the mirrored
    mechanism is written instead (the same lengths, the strokes swapped)."""
    text = mechanism_toml(syn, task, default_name=default_name)
    mech, c, chk = check_text(text, source)
    mirrored = False
    if chk.time_ratio is not None and chk.time_ratio < 1.0 - 1e-9:
        text2 = mechanism_toml(syn, task, mirror=True, default_name=default_name)
        mech2, c2, chk2 = check_text(text2, source)
        if chk2.time_ratio is not None and chk2.time_ratio > chk.time_ratio:
            text, mech, c, chk, mirrored = text2, mech2, c2, chk2, True
    return Synthesised(task, syn, text, mech, c, chk, mirrored, _notes(task, syn, chk, mirrored))


@record(eq=False)
class Recorded:
    """The synthesis a mechanism file records (its [synthesis] table), done again from the task."""

    task: object  # synthesis_task.Task
    synthesis: object  # SliderSynthesis | RockerSynthesis | SlottedSynthesis
    matches: bool  # the file's lengths are the synthesis's (False: edited after tmm synth)


def _file_lengths(mech) -> tuple[float, ...]:
    g = mech.groups
    frame = list(mech.frame.values())
    dist = abs(frame[-1] - frame[0]) if len(frame) > 1 else 0.0
    along = {p.name: p.along for p in mech.points}
    return (mech.crank.length, *[x for grp in g for x in grp.lengths], dist, along.get("B", 0.0))


def _synthesis_lengths(syn) -> tuple[float, ...]:
    if isinstance(syn, SliderSynthesis):
        return (syn.crank, syn.rod, 0.0, 0.0)
    if isinstance(syn, RockerSynthesis):
        return (syn.crank, syn.coupler, syn.rocker, syn.frame, 0.0)
    return (syn.crank, syn.rod, syn.frame, syn.link)


LENGTH_NAMES = {"crank-slider": ("l_OA", "l_AB", None, None), "crank-rocker": ("l_AB", "l_BC", "l_CD", "l_AD", None),
                "slotted-link": ("l_O1A", "l_BC", "l_O1O2", "l_O2B")}  # in the order of _synthesis_lengths


def changed_lengths(mech, rec: Recorded) -> tuple[tuple[str, float, float], ...]:
    """The lengths of the file that differ from the synthesis it records: (the book's name, the
    file's [m], the synthesis' [m]), in the order crank, coupler/rod, rocker, frame, link."""
    have, want = _file_lengths(mech), _synthesis_lengths(rec.synthesis)
    names = LENGTH_NAMES[rec.task.type]
    if len(have) != len(want):
        return ()
    return tuple((n, a, b) for n, a, b in zip(names, have, want)
                 if n is not None and abs(a - b) > 1e-9 * max(abs(b), 1e-3))


def recorded_synthesis(mech) -> Recorded | None:
    """The synthesis recorded in the mechanism's [synthesis] table, or None (no table, or a table
    that is not a task tmm synth can do again). `matches` says whether the file still has the
    lengths the synthesis found (to 1e-9).

    >>> from .mechanism_file import parse_mechanism
    >>> from .synthesis_task import parse_task, synthesise
    >>> t = parse_task({"type": "crank-slider", "stroke": 0.12, "lambda": 0.25})
    >>> mech = parse_mechanism(tomllib.loads(mechanism_toml(synthesise(t), t)))
    >>> r = recorded_synthesis(mech)
    >>> r.task.type, round(r.synthesis.rod, 12), r.matches
    ('crank-slider', 0.24, True)
    """
    from ..errors import TmmError
    from .synthesis_task import parse_task, synthesise

    rec = mech.extra.get("synthesis")
    if not isinstance(rec, dict):
        return None
    try:
        task = parse_task(dict(rec), "synthesis")
        syn = synthesise(task)
    except TmmError:
        return None
    have, want = _file_lengths(mech), _synthesis_lengths(syn)
    matches = len(have) == len(want) and all(abs(a - b) <= 1e-9 * max(abs(b), 1e-3) for a, b in zip(have, want))
    return Recorded(task, syn, matches)
