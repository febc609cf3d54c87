"""Reducer accuracy: planet-carrier bore positions from a measurement card (seed 004) and
dimensional chains (seed 003, second article)."""
