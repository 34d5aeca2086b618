# Type stubs for linkwright (the extension _linkwright, re-exported). See docs/python.md.
from typing import Literal, Optional

import numpy
import numpy.ma

class Error(ValueError):
    """A refusal of Linkwright's core: the message names the field, the value and the range."""

    field: str
    code: Literal["invalid-value", "invalid-structure", "not-assemblable", "singular", "cancelled"]

class SweepWarning(UserWarning):
    """What linkwright-cli analyze notes on stderr: rows left out, toggles, locks."""

class Linkage:
    """A planar linkage with the input grid linkwright-cli analyze uses for it."""

    @property
    def kind(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def length_unit(self) -> str: ...
    @property
    def points(self) -> list[str]: ...
    @property
    def links(self) -> list[str]: ...
    def sweep(
        self,
        start_deg: Optional[float] = None,
        stop_deg: Optional[float] = None,
        samples: Optional[int] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
    ) -> dict[str, numpy.ma.MaskedArray]:
        """The sweep as columns named as linkwright-cli analyze's; undefined entries masked."""
    def sweep_csv(
        self,
        start_deg: Optional[float] = None,
        stop_deg: Optional[float] = None,
        samples: Optional[int] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
    ) -> str:
        """The sweep as CSV text, byte for byte linkwright-cli analyze's."""
    def classify(self) -> dict[str, object]:
        """Mobility, assembly ranges, Grashof class, transmission range, quick-return figures."""

def examples() -> list[str]:
    """The built-in examples' names."""

def example(name: str) -> Linkage:
    """The built-in example `name`."""

def four_bar(
    frame: float,
    crank: float,
    coupler: float,
    rocker: float,
    unit: str = "mm",
    branch: Literal["open", "crossed"] = "open",
    coupler_point: Optional[tuple[float, float]] = None,
) -> Linkage:
    """A four-bar from its lengths."""

def load(path: str) -> Linkage:
    """A Linkwright document."""
