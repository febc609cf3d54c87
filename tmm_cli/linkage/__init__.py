"""Linkage kinematics (seed 003): the slotted-link (Whitworth) quick-return mechanism."""
