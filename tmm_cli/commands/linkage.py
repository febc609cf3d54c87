"""`tmm linkage`: kinematics of the slotted-link (Whitworth) quick-return mechanism (seed 003)."""

from __future__ import annotations

import click

from ..cli import CONTEXT
from ..errors import TmmError


@click.command("linkage", context_settings=CONTEXT)
def linkage_cmd():
    """Sheet 1: slotted-link (Whitworth) mechanism — positions, velocities, accelerations."""
    raise TmmError("tmm linkage is not built yet")
