"""Linkwright's kinematics core in Python: planar linkages swept to NumPy columns.

    >>> import linkwright
    >>> crank_rocker = linkwright.example("thesis-crank-rocker")
    >>> table = crank_rocker.sweep()            # dict: CLI column name -> numpy.ma.MaskedArray
    >>> table["rocker_omega_rad_s"].max()

The numbers are the core's, the column names and units are linkwright-cli's, and every refusal
is a linkwright.Error (a ValueError) carrying the core's sentence; what linkwright-cli notes on
stderr about a sweep is a linkwright.SweepWarning. See docs/python.md.
"""

from ._linkwright import (
    PATH_STARTS_PER_BLOCK,
    Atlas,
    Error,
    Linkage,
    PathSearch,
    PathStartBlock,
    SweepWarning,
    accuracy,
    arm,
    example,
    examples,
    four_bar,
    load,
    synthesize_crank_rocker,
    synthesize_function,
    synthesize_motion,
    synthesize_shaper,
    synthesize_slider_crank,
)

# A traceback names the refusal as it is imported, linkwright.Error (docs/python.md), not by
# the extension it is defined in (linkwright._linkwright.Error); pickles name it so too.
Error.__module__ = __name__

__all__ = [
    "PATH_STARTS_PER_BLOCK",
    "Atlas",
    "Error",
    "Linkage",
    "PathSearch",
    "PathStartBlock",
    "SweepWarning",
    "accuracy",
    "arm",
    "example",
    "examples",
    "four_bar",
    "load",
    "synthesize_crank_rocker",
    "synthesize_function",
    "synthesize_motion",
    "synthesize_shaper",
    "synthesize_slider_crank",
]
