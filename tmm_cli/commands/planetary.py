"""`tmm planetary`: planetary synthesis with different meshing angles, shifted gears (seed 000)."""

from __future__ import annotations

import click

from ..cli import CONTEXT
from ..errors import TmmError


@click.command("planetary", context_settings=CONTEXT)
def planetary_cmd():
    """Planetary mechanism AA̅ with shifted gears and different meshing angles (seed 000)."""
    raise TmmError("tmm planetary is not built yet")
