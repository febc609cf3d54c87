"""The one error type the core raises for bad input or impossible synthesis.

The CLI turns it into a one-line message and exit status 2 (no traceback).
"""


class TmmError(ValueError):
    """Bad input or an impossible synthesis; the message names the problem and the fix."""
