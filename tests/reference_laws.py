"""The four acceleration laws written out again for the tests, independently of tmm_cli.cam.laws
(METHOD.md, "Inputs"): normalised displacement f(t) on t ∈ [0, 1]."""

import numpy as np


def law_f(law, t):
    t = np.clip(t, 0.0, 1.0)
    if law == 1:
        return np.where(t < 0.5, 2 * t**2, 1 - 2 * (1 - t) ** 2)
    if law == 2:
        return 3 * t**2 - 2 * t**3
    if law == 3:
        return (1 - np.cos(np.pi * t)) / 2
    return t - np.sin(2 * np.pi * t) / (2 * np.pi)
