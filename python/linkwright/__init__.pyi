# Type stubs for linkwright (the extension _linkwright, re-exported). See docs/python.md.
from typing import Any, Literal, Optional, Sequence, overload

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
        forces: bool = False,
        *,
        law: Optional[Literal["constant", "ramp", "cycloidal", "345", "table"]] = None,
        ramp_time_s: Optional[float] = None,
        rise_deg: Optional[float] = None,
        duration_s: Optional[float] = None,
        law_table: Optional[str] = None,
        from_time_s: Optional[float] = None,
        to_time_s: Optional[float] = None,
        step_time_s: Optional[float] = None,
    ) -> dict[str, numpy.ma.MaskedArray]:
        """The sweep as columns named as linkwright-cli analyze's; undefined entries masked.
        forces=True adds analyze --forces's columns (a linkage with masses)."""
    def sweep_csv(
        self,
        start_deg: Optional[float] = None,
        stop_deg: Optional[float] = None,
        samples: Optional[int] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
        forces: bool = False,
        *,
        law: Optional[Literal["constant", "ramp", "cycloidal", "345", "table"]] = None,
        ramp_time_s: Optional[float] = None,
        rise_deg: Optional[float] = None,
        duration_s: Optional[float] = None,
        law_table: Optional[str] = None,
        from_time_s: Optional[float] = None,
        to_time_s: Optional[float] = None,
        step_time_s: Optional[float] = None,
    ) -> str:
        """The sweep as CSV text, byte for byte linkwright-cli analyze's (analyze --forces's with forces)."""
    def classify(self) -> dict[str, object]:
        """Mobility, assembly ranges, Grashof class, transmission range, quick-return figures."""
    def extremes(
        self,
        start_deg: Optional[float] = None,
        stop_deg: Optional[float] = None,
        samples: Optional[int] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
    ) -> dict[str, dict[str, Optional[float]]]:
        """Each column's refined min and max and where: {min, min_at_deg, max, max_at_deg}."""
    def machine(
        self,
        *,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        samples: Optional[int] = None,
        tolerance: Optional[float] = None,
        cs: Optional[float] = None,
        gear_ratio: Optional[float] = None,
        efficiency: Optional[float] = None,
        rated_torque: Optional[float] = None,
        rated_speed: Optional[float] = None,
    ) -> dict[str, Any]:
        """What one crank turn asks of the machine, as linkwright-cli machine --json, converged to
        `tolerance` (each figure's estimate under 'accuracy'), with the turn's curves as arrays."""
    def instant_centres(self, at: float) -> dict[str, Any]:
        """Every pair of bodies' instant centre at input `at`, the velocity ratio and mechanical advantage."""
    @overload
    def polygons(
        self, at: float, *, rpm: Optional[float] = None, omega: Optional[float] = None, alpha: Optional[float] = None
    ) -> dict[str, Any]:
        """The velocity and acceleration polygons at crank angle `at` (degrees), as linkwright-cli polygon --json."""
    @overload
    def polygons(
        self,
        at: Sequence[float],
        *,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
    ) -> list[dict[str, Any]]:
        """The polygons at each crank angle of `at`, in order."""
    def inversions(self) -> dict[str, Any]:
        """A four-bar's or slider-crank's four inversions, as linkwright-cli inversions --json."""
    def cognates(self, output: Optional[str] = None, *, coupler_point: Optional[str] = None) -> dict[str, Any]:
        """The two Roberts-Chebyshev cognates, as linkwright-cli cognates --json, each with its 'linkage';
        with output=PREFIX written to PREFIX-1.linkwright and PREFIX-2.linkwright."""
    def balance(
        self,
        output: Optional[str] = None,
        *,
        fraction: Optional[float] = None,
        radius: Optional[float] = None,
        spring: Optional[tuple[str, str]] = None,
        spring_search: Optional[str] = None,
    ) -> dict[str, Any]:
        """Counterweights, or the spring that makes the RMS driving torque least, as linkwright-cli balance
        --json, with the balanced 'linkage'; with output=PATH the design written there."""
    def dxf(
        self, output: str, *, at: Optional[float] = None, hole: Optional[float] = None, width: Optional[float] = None
    ) -> dict[str, Any]:
        """Writes the links at input `at` as a DXF drawing to `output`, the bytes linkwright-cli dxf writes."""
    def tolerance_study(
        self,
        tolerance: float,
        *,
        mc_samples: int = 1000,
        seed: int = 46,
        first_sample: int = 0,
        start_deg: Optional[float] = None,
        stop_deg: Optional[float] = None,
        samples: Optional[int] = None,
        omega: Optional[float] = None,
        alpha: Optional[float] = None,
        per_dimension: dict[str, float] = {},
    ) -> dict[str, Any]:
        """The seeded Monte-Carlo tolerance study over samples [first_sample, first_sample + mc_samples);
        per_dimension gives dimensions a ± of their own."""

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

def accuracy(*, example: Optional[str] = None, output: Optional[str] = None) -> dict[str, Any]:
    """The speed-accuracy trade, measured, as linkwright-cli accuracy: the CLI's columns, the errors
    at full precision (example, method and reference as lists, the numbers as arrays)."""

def arm(
    *,
    example: Optional[Literal["seed-arm"]] = None,
    arm: Optional[tuple[float, float]] = None,
    from_point: Optional[tuple[float, float]] = None,
    to_point: Optional[tuple[float, float]] = None,
    speed: Optional[float] = None,
    elbow: Optional[Literal["up", "down"]] = None,
    samples: Optional[int] = None,
    step_time: Optional[float] = None,
    unit: str = "m",
    output: Optional[str] = None,
    table: bool = False,
) -> dict[str, numpy.ma.MaskedArray]:
    """The two-link arm with its tip on a line at constant speed, as linkwright-cli arm: its columns
    as masked arrays (masked where the CLI leaves a cell empty), its notes as SweepWarnings."""

PATH_STARTS_PER_BLOCK: int

class PathStartBlock:
    """One block of a path search's starts; picklable."""

    @property
    def block(self) -> int: ...
    @property
    def starts_run(self) -> int: ...
    @property
    def kept(self) -> int: ...

class PathSearch:
    """A path synthesis (linkwright-cli synthesize path), whole or in blocks; picklable."""

    def __init__(
        self,
        points: Sequence[tuple[float, float]],
        *,
        timing_deg: Optional[Sequence[float]] = None,
        timing_from: Literal["start", "frame"] = "start",
        full_rotation: bool = False,
        unit: str = "mm",
        starts: int = 400,
        seed: int = 19,
        keep: int = 10,
        max_evaluations: int = 200,
    ) -> None: ...
    @property
    def blocks(self) -> int: ...
    def run(self) -> dict[str, Any]:
        """The whole search: candidates best first, scale, starts_run, starts_not_assembled, cancelled."""
    def run_block(self, block: int) -> PathStartBlock:
        """Block `block` of the search, alone."""
    def merge(self, blocks: Sequence[PathStartBlock]) -> dict[str, Any]:
        """run()'s answer from its blocks, to the last bit."""

def synthesize_crank_rocker(swing_deg: float, *, time_ratio: float = 1.0, length: float = 1.0,
                            scale: Literal["rocker", "frame"] = "rocker", unit: str = "mm") -> dict[str, Any]:
    """A crank-rocker for a swing and time ratio (linkwright-cli synthesize swing)."""

def synthesize_slider_crank(stroke: float, *, time_ratio: float = 1.0, rod: Optional[float] = None,
                            offset: Optional[float] = None, unit: str = "mm") -> dict[str, Any]:
    """A slider-crank for a stroke and time ratio, its rod or offset given (synthesize slider)."""

def synthesize_shaper(stroke: float, *, time_ratio: float = 1.5, crank: float, link: float,
                      guide_height: Optional[float] = None, unit: str = "mm") -> dict[str, Any]:
    """A crank-shaper for a stroke and time ratio (synthesize shaper)."""

def synthesize_motion(poses: Sequence[tuple[float, float, float]], *, circle_a: tuple[float, float],
                      circle_b: tuple[float, float], centre_a: Optional[float] = None,
                      centre_b: Optional[float] = None, full_rotation: bool = False,
                      unit: str = "mm") -> dict[str, Any]:
    """A motion generator through 2 or 3 coupler poses (x, y, angle_deg) (synthesize motion)."""

def synthesize_function(function: str, *, x0: float, x1: float, input_start_deg: float, input_span_deg: float,
                        output_start_deg: float, output_span_deg: float, frame: float = 100.0,
                        points: Optional[Sequence[float]] = None, count: int = 3,
                        unit: str = "mm") -> dict[str, Any]:
    """A Freudenstein function generator (synthesize function)."""

class Atlas:
    """The coupler-curve atlas's grid (linkwright-cli atlas); picklable."""

    def __init__(
        self,
        *,
        coupler: Sequence[float] = (1.5, 2.0, 2.5, 3.0),
        rocker: Sequence[float] = (1.5, 2.0, 2.5, 3.0),
        frame: Sequence[float] = (2.0, 2.5, 3.0),
        along: Sequence[float] = (0.0, 0.5, 1.0, 1.5, 2.0),
        across: Sequence[float] = (0.0, 0.5, 1.0),
        branch: Literal["open", "crossed"] = "open",
        samples: int = 360,
    ) -> None: ...
    @property
    def cells(self) -> int: ...
    def page(self, first: int = 0, count: Optional[int] = None, filter: Optional[str] = None) -> list[dict[str, Any]]:
        """Cells [first, first + count), computed and classified; filter keeps those with every feature named."""
    def linkage(self, cell: int, *, crank: float = 1.0, unit: str = "mm") -> Linkage:
        """The cell's four-bar as a Linkage."""
