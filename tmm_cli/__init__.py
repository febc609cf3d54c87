"""tmm — the course-project calculator for the Theory of Mechanisms and Machines.

Sheet 3 (cam mechanism, book section 1) lives in :mod:`tmm_cli.cam`, sheet 4 (gear drive,
book section 2) in :mod:`tmm_cli.gears`. The computation modules are pure: they take plain
inputs and return frozen dataclasses. :mod:`tmm_cli.cli` is the thin click shell.
"""

__version__ = "0.1.0"
