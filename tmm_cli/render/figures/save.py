"""Saving drawn figures into a staging folder."""

from __future__ import annotations

from pathlib import Path


def save_figures(folder: Path, figures: dict, fmt: str = "png", dpi: int = 120) -> list[Path]:
    """Save matplotlib Figures as ``folder/<name>.<fmt>``; returns the paths in order."""
    paths = []
    for name, fig in figures.items():
        p = Path(folder) / f"{name}.{fmt}"
        fig.savefig(p, format=fmt, dpi=dpi)  # every figure uses the constrained layout
        paths.append(p)
    return paths
