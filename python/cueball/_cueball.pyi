"""Type stubs of the extension module cueball._cueball (python/src/), with units;
the package cueball re-exports all of it.

SI throughout: m, s, kg, rad; degrees and ball radii only in the scenario's
units (ShotStrike, scenario JSON, simulate_many's actions, CueStrike.from_units).
Every params= defaults to pool_parameters(), as the default table, rack and
scenario. Table frame: x, y on the bed, z up. Vectors
are tuples (x, y) or (wx, wy, wz); any sequence or NumPy array of the right
length is accepted, and NumPy scalars wherever a number is. Checked against
the module by python/tests/test_stubs.py (every public name) and by
`mypy --strict` on python/tests/typed_usage.py.
"""

import os
from typing import Any, Iterable, Mapping, Sequence, TypedDict

import numpy as np
from numpy.typing import NDArray

__version__: str

_Float = float | np.floating[Any] | np.integer[Any]
_Int = int | np.integer[Any]
_Vec = Sequence[_Float] | NDArray[Any]
_Scenario = None | Scenario | str | os.PathLike[str] | Mapping[str, Any]

# ------------------------------------------------------------------ errors

class InvalidArgument(ValueError):
    """A value outside its allowed range; `field` names it (e.g. 'mu_s', 'scenario.balls[1].position')."""

    field: str

class InvalidArgumentType(InvalidArgument, TypeError):
    """An argument of the wrong Python type; `field` names the argument (e.g. 'speed')."""

class InfeasibleShot(ValueError):
    """A plan with no physical answer; `condition` is the failed inequality (e.g. 'x1 >= x0')."""

    condition: str

class SimulationError(RuntimeError):
    """A simulation that could not finish (it reached the scenario's max_events)."""

class NoFeasibleShot(ValueError):
    """plan_shot found no strike of the requested kinds that pots the ball; the message says why."""

# ------------------------------------------------------------------ parameters

class BallParameters:
    """The ball."""

    mass: float
    """m, kg"""
    radius: float
    """R, m"""
    def __init__(self, mass: _Float, radius: _Float) -> None: ...

class ClothParameters:
    """The cloth: friction coefficients (dimensionless) and gravity (m/s^2)."""

    sliding_friction: float
    """mu_s; a sliding ball decelerates at mu_s g"""
    rolling_resistance: float
    """mu_r (paper 001's energy convention): a rolling ball decelerates at (5/7) mu_r g"""
    spin_friction: float
    """mu_sp: dw_z/dt = -5 mu_sp g / (2R)"""
    gravity: float
    """g, m/s^2"""
    def __init__(
        self, sliding_friction: _Float, rolling_resistance: _Float, spin_friction: _Float, gravity: _Float = 9.81
    ) -> None: ...

class Parameters:
    """Ball and cloth (read/write, picklable)."""

    ball: BallParameters
    cloth: ClothParameters
    def __init__(self, ball: BallParameters, cloth: ClothParameters) -> None: ...

def snooker_parameters() -> Parameters:
    """Snooker ball on a snooker cloth (Mathavan 2010)."""

def pool_parameters() -> Parameters:
    """WPA pool ball on a typical pool cloth (the default of every params=)."""

def carom_parameters() -> Parameters:
    """UMB carom ball on a heated carom cloth (fitted to a recorded three-cushion match)."""

def preset_parameters(name: str) -> Parameters:
    """'snooker' or 'pool'; InvalidArgument otherwise."""

def validate(params: Parameters) -> None:
    """Raises InvalidArgument naming the first parameter out of its range (PARAMETER_RANGES)."""

def moment_of_inertia(ball: BallParameters) -> float:
    """I = 2/5 m R^2, kg m^2."""

def sliding_deceleration(params: Parameters) -> float:
    """mu_s g, m/s^2."""

def rolling_deceleration(params: Parameters) -> float:
    """(5/7) mu_r g, m/s^2."""

def spin_deceleration(params: Parameters) -> float:
    """5 mu_sp g / (2R), rad/s^2."""

PARAMETER_RANGES: dict[str, dict[str, Any]]
"""{field: {'min', 'max', 'unit', 'meaning'}}"""

# ------------------------------------------------------------------ cloth motion

class BallState:
    """A ball on the bed: position (x, y) m, velocity (vx, vy) m/s, angular_velocity (wx, wy, wz) rad/s."""

    @property
    def position(self) -> tuple[float, float]: ...
    @position.setter
    def position(self, value: _Vec) -> None: ...
    @property
    def velocity(self) -> tuple[float, float]: ...
    @velocity.setter
    def velocity(self, value: _Vec) -> None: ...
    @property
    def angular_velocity(self) -> tuple[float, float, float]: ...
    @angular_velocity.setter
    def angular_velocity(self, value: _Vec) -> None: ...
    def __init__(
        self, position: _Vec = (0.0, 0.0), velocity: _Vec = (0.0, 0.0), angular_velocity: _Vec = (0.0, 0.0, 0.0)
    ) -> None: ...

def slip_velocity(state: BallState, params: Parameters = ...) -> tuple[float, float]:
    """Contact-point slip u = v + R z^ x w, m/s."""

def motion_phase(state: BallState, params: Parameters = ...) -> str:
    """'sliding', 'rolling', 'spinning' or 'stationary'."""

def next_transition(state: BallState, params: Parameters = ...) -> tuple[float, str]:
    """(time s, kind): 'sliding_ends', 'rolling_ends', 'vertical_spin_ends' or 'none' (time inf)."""

def phase_end_time(state: BallState, params: Parameters = ...) -> float:
    """Seconds until the path changes (ignoring vertical spin); inf at rest."""

def evolve(state: BallState, dt: _Float, params: Parameters = ...) -> BallState:
    """The state after dt >= 0 s, in closed form."""

def kinetic_energy(state: BallState, params: Parameters = ...) -> float:
    """Translational plus rotational kinetic energy, J."""

class StraightShot:
    """A straight shot along +x from x = 0 (paper 001 eqs 19-24)."""

    t1: float
    """end of sliding, s"""
    x1: float
    """position at the end of sliding, m"""
    v1: float
    """velocity at the end of sliding, m/s"""
    t2: float
    """the ball stops translating, s"""
    x2: float
    """rest position, m"""
    t_spin: float
    """vertical spin reaches zero, s"""

def straight_shot(v0: _Float, w0: _Float = 0.0, side_spin: _Float = 0.0, params: Parameters = ...) -> StraightShot:
    """Speed v0 m/s along +x, topspin w0 rad/s (R w0 = v0 natural roll), side spin w_z rad/s."""

def straight_shot_state(
    v0: _Float, w0: _Float = 0.0, side_spin: _Float = 0.0, t: _Float = 0.0, params: Parameters = ...
) -> BallState:
    """The state of straight_shot(v0, w0, side_spin) at time t >= 0 s."""

MAX_SPEED: float
"""m/s"""
MAX_ANGULAR_SPEED: float
"""rad/s"""

# ------------------------------------------------------------------ planner

class ShotPlan:
    """Initial speed and topspin that bring a ball to x2 with speed v2 (paper 001 eqs 17-28)."""

    variant: str
    """'given_slide_end', 'natural_roll', 'given_spin' or 'given_speed'"""
    v0: float
    """m/s"""
    w0: float
    """rad/s"""
    t1: float
    """s"""
    x1: float
    """m"""
    v1: float
    """m/s"""
    t2: float
    """s"""

def plan_shot_with_slide_end(
    *, x1: _Float, x2: _Float, v2: _Float = 0.0, x0: _Float = 0.0, params: Parameters = ...
) -> ShotPlan:
    """Sliding ends at x1 (m); the ball passes x2 (m) at v2 (m/s)."""

def plan_shot_with_spin(
    *, w0: _Float, x2: _Float, v2: _Float = 0.0, x0: _Float = 0.0, params: Parameters = ...
) -> ShotPlan:
    """Given topspin w0 (rad/s)."""

def plan_shot_with_speed(
    *, v0: _Float, x2: _Float, v2: _Float = 0.0, x0: _Float = 0.0, params: Parameters = ...
) -> ShotPlan:
    """Given speed v0 (m/s)."""

def plan_natural_roll_shot(*, x2: _Float, v2: _Float = 0.0, x0: _Float = 0.0, params: Parameters = ...) -> ShotPlan:
    """Natural roll from the start (x1 = x0, R w0 = v0)."""

# ------------------------------------------------------------------ cue strike

class CueParameters:
    """The cue."""

    mass: float
    """M_c, kg"""
    tip_restitution: float
    """e, [0, 1]"""
    end_mass: float
    """m_e, kg, [0, 0.05]: the shaft's end mass of squirt; 0: no squirt"""
    def __init__(self, mass: _Float = 0.54, tip_restitution: _Float = 0.75, end_mass: _Float = 0.008) -> None: ...

class CueStrike:
    """One stroke of the cue (Leckie & Greenspan 2006)."""

    speed: float
    """V, m/s, (0, 12]"""
    aim: float
    """phi, rad, anticlockwise from +x"""
    elevation: float
    """theta, rad, [0, pi/2)"""
    side_offset: float
    """a, m; > 0 right english (w_z > 0)"""
    height_offset: float
    """b, m; > 0 above the centre"""
    def __init__(
        self,
        speed: _Float,
        aim: _Float = 0.0,
        elevation: _Float = 0.0,
        side_offset: _Float = 0.0,
        height_offset: _Float = 0.0,
    ) -> None: ...
    @staticmethod
    def from_units(
        speed: _Float,
        aim_deg: _Float = 0.0,
        elevation_deg: _Float = 0.0,
        side: _Float = 0.0,
        height: _Float = 0.0,
        *,
        radius: _Float = 0.028575,
    ) -> CueStrike:
        """From the scenario's units (m/s, degrees, ball radii of a ball of radius m), as its reader converts."""
    def in_units(self, *, radius: _Float = 0.028575) -> dict[str, float]:
        """The scenario's units: {speed m/s, aim_deg, elevation_deg degrees, side, height ball radii}."""

def strike_ball(
    strike: CueStrike, position: _Vec = (0.0, 0.0), params: Parameters = ..., cue: CueParameters = ...
) -> BallState:
    """The ball just after the strike at position (x, y) m; a miscue raises InvalidArgument ('tip offset')."""

def cue_tip_offset_ok(strike: CueStrike, params: Parameters = ...) -> bool:
    """True when sqrt(a^2 + b^2) <= 0.5 R."""

def level_cue_tip_height(v0: _Float, w0: _Float, params: Parameters = ...) -> float:
    """Tip height b, m, for a level cue giving speed v0 m/s and topspin w0 rad/s."""

def level_cue_speed(v0: _Float, tip_height: _Float, params: Parameters = ..., cue: CueParameters = ...) -> float:
    """Cue speed V, m/s, giving ball speed v0 with a level cue at tip_height m."""

MAX_CUE_SPEED: float
"""m/s"""
MISCUE_OFFSET_FRACTION: float
"""of R"""

# ------------------------------------------------------------------ cushion impact

class CushionImpactSample:
    """The impact at one normal impulse P_I (cushion frame: X along it, Y into it, Z up)."""

    normal_impulse: float
    """P_I, N s"""
    cushion_slip_speed: float
    """m/s"""
    cushion_slip_angle: float
    """rad"""
    bed_slip_speed: float
    """m/s"""
    bed_slip_angle: float
    """rad"""
    @property
    def velocity(self) -> tuple[float, float, float]:
        """m/s"""
    @property
    def angular_velocity(self) -> tuple[float, float, float]:
        """rad/s"""
    work: float
    """J"""

class CushionImpactResult:
    """The ball after a cushion impact, in the cushion frame."""

    @property
    def velocity(self) -> tuple[float, float, float]:
        """(vX, vY, vZ), m/s"""
    @property
    def angular_velocity(self) -> tuple[float, float, float]:
        """(wX, wY, wZ), rad/s"""
    rebound_speed: float
    """m/s"""
    rebound_angle: float
    """rad from the cushion line"""
    compression_impulse: float
    """N s"""
    total_impulse: float
    """N s"""
    compression_work: float
    """J, negative"""
    beyond_rigid_cushion_limit: bool
    solver_steps: int
    solver_events: int
    history: list[CushionImpactSample]

def cushion_impact(
    speed: _Float,
    angle: _Float,
    topspin: _Float | None = None,
    sidespin: _Float = 0.0,
    *,
    params: Parameters = ...,
    restitution: _Float = 0.98,
    friction: _Float = 0.14,
    contact_height: _Float | None = None,
    solver: str = "exact",
    paper_steps: _Int = 5000,
    history: bool = False,
    exact_tolerance: _Float = 1e-8,
    rolling_table: bool = True,
) -> CushionImpactResult:
    """Mathavan 2010: speed V0 m/s, angle alpha rad in (0, pi/2], spins rad/s (topspin None: rolling).

    exact_tolerance in [1e-11, 1e-7]; rolling_table=False when sweeping the constants."""

RIGID_CUSHION_SPEED_LIMIT: float
"""m/s"""

class CushionRebound:
    """The ball after a cushion impact by any model, in the cushion frame."""

    @property
    def velocity(self) -> tuple[float, float, float]:
        """(vX, vY, vZ), m/s"""
    @property
    def angular_velocity(self) -> tuple[float, float, float]:
        """(wX, wY, wZ), rad/s"""
    @property
    def rebound_speed(self) -> float:
        """m/s"""
    @property
    def rebound_angle(self) -> float:
        """rad from the cushion line"""

def cushion_rebound(
    speed: _Float,
    angle: _Float,
    topspin: _Float | None = None,
    sidespin: _Float = 0.0,
    *,
    model: str = "mathavan_2010",
    params: Parameters = ...,
    restitution: _Float | None = None,
    friction: _Float | None = None,
    contact_height: _Float | None = None,
    frequency_ratio: _Float | None = None,
) -> CushionRebound:
    """The impact by the model named ('mathavan_2010', 'han_2005', 'stronge_compliant'), its own constants unless given."""

# ------------------------------------------------------------------ cushion fit

class PaperIncidence:
    """A ball arriving at a cushion (Mathavan 2010, section 3.1), as cushion_impact's arguments."""

    speed: float
    """V0 > 0, m/s"""
    angle: float
    """alpha, rad, (0, pi/2]; pi/2 is head-on"""
    topspin: float
    """w_T, rad/s; V0/R is rolling"""
    sidespin: float
    """w_S, rad/s about Z"""
    def __init__(self, speed: _Float, angle: _Float, topspin: _Float, sidespin: _Float = 0.0) -> None: ...

class HeadOnRebound:
    """A head-on impact of a rolling ball without side spin."""

    incoming_speed: float
    """V0, m/s"""
    rebound_speed: float
    """measured, m/s"""
    def __init__(self, incoming_speed: _Float, rebound_speed: _Float) -> None: ...

class ObliqueRebound:
    """Any impact: its incidence and the measured rebound."""

    incidence: PaperIncidence
    rebound_speed: float
    """m/s"""
    rebound_angle: float
    """beta, rad from the cushion line"""
    def __init__(self, incidence: PaperIncidence, rebound_speed: _Float, rebound_angle: _Float) -> None: ...

class CushionFitData:
    """Measured rebounds (assign new lists to change them)."""

    head_on: list[HeadOnRebound]
    oblique: list[ObliqueRebound]
    def __init__(self, head_on: Sequence[HeadOnRebound] = ..., oblique: Sequence[ObliqueRebound] = ...) -> None: ...

class CushionFitOptions:
    """How to fit: solver 'exact' or 'paper', its steps, the grid step, the contact height (m; 0: 7R/5)."""

    solver: str
    paper_steps: int
    grid_step: float
    contact_height: float
    """h, m; 0 means 7R/5"""
    def __init__(
        self, solver: str = "exact", paper_steps: _Int = 5000, grid_step: _Float = 0.01, contact_height: _Float = 0.0
    ) -> None: ...

class CushionFit:
    """The fitted e_e and mu_w and how well the data determine them."""

    @property
    def restitution(self) -> float:
        """e_e"""
    @property
    def friction(self) -> float:
        """mu_w"""
    @property
    def residual(self) -> float:
        """sum of squared errors, m^2/s^2"""
    @property
    def grid_restitution(self) -> float: ...
    @property
    def grid_friction(self) -> float: ...
    @property
    def grid_residual(self) -> float: ...
    @property
    def restitution_sigma(self) -> float:
        """standard error (inf: undetermined)"""
    @property
    def friction_sigma(self) -> float:
        """standard error (inf: undetermined)"""
    @property
    def correlation(self) -> float: ...
    @property
    def condition_number(self) -> float: ...
    @property
    def poorly_separated(self) -> bool:
        """the data fix only one combination of e_e and mu_w"""
    @property
    def friction_upper_bound(self) -> float:
        """tan(theta)"""
    @property
    def residuals(self) -> int: ...
    @property
    def impacts_solved(self) -> int: ...
    @property
    def beyond_rigid_cushion_limit(self) -> int: ...

def fit_cushion(data: CushionFitData, params: Parameters = ..., options: CushionFitOptions = ...) -> CushionFit:
    """Fits e_e and mu_w to measured rebounds (Mathavan 2010, section 3.5); releases the GIL."""

# ------------------------------------------------------------------ calibration

def calibrate(
    shots: str,
    *,
    held_out: float = 0.25,
    seed: int = 0,
    constants: str | None = None,
    evaluate: bool = False,
    cushion_model: str | None = None,
    ball_collision_model: str | None = None,
    threads: int = 1,
    starts: int = 32,
    max_evaluations: int = 300,
    max_iterations: int = 20,
    restarts: int = 2,
    spin_profile: int = 7,
    bootstrap: int = 0,
    html: bool = False,
) -> dict[str, Any]:
    """Fits strikes and the table's constants to tracked shots (JSON text); the report as a dict
    (with html=True, the HTML report's page in its "html")."""

# ------------------------------------------------------------------ ball-ball collision

class BallCollisionParameters:
    """mu(u) = friction + friction_excess * exp(-friction_decay * u), u the slip speed in m/s."""

    restitution: float
    """e, [0, 1]"""
    friction: float
    """[0, 1]"""
    friction_excess: float
    """[0, 1]"""
    friction_decay: float
    """s/m, [0, 100]"""
    def __init__(
        self, restitution: _Float, friction: _Float = 0.0, friction_excess: _Float = 0.0, friction_decay: _Float = 0.0
    ) -> None: ...

def ball_collision_alciatore() -> BallCollisionParameters:
    """e = 0.95 with Alciatore's friction fit (the simulator's default)."""

def ball_collision_frictionless(restitution: _Float) -> BallCollisionParameters:
    """No friction: the impulse along the line of centres only."""

def ball_friction(contact: BallCollisionParameters, slip_speed: _Float) -> float:
    """mu at slip speed (m/s, >= 0)."""

def balls_approaching(a: BallState, b: BallState) -> bool:
    """(r_b - r_a) . (v_b - v_a) < 0."""

class BallCollisionResult:
    """The states just after the impact and the impulses on b (N s; on a the opposite)."""

    @property
    def a(self) -> BallState: ...
    @property
    def b(self) -> BallState: ...
    @property
    def normal_impulse(self) -> float:
        """N s, along n = (r_b - r_a)/|r_b - r_a|"""
    @property
    def tangential_impulse(self) -> float:
        """N s, along z x n"""
    @property
    def vertical_impulse(self) -> float:
        """N s, taken up by the bed"""
    @property
    def friction(self) -> float: ...
    @property
    def slip_speed(self) -> float:
        """m/s"""
    @property
    def gripped(self) -> bool: ...

def resolve_ball_collision(
    a: BallState, b: BallState, params: Parameters = ..., contact: BallCollisionParameters = ...
) -> BallCollisionResult:
    """Two identical touching balls colliding (Alciatore; Mathavan 2014); params.ball gives R and m."""

def collide_balls(
    a: BallState, b: BallState, params: Parameters = ..., contact: BallCollisionParameters = ...
) -> tuple[BallState, BallState]:
    """resolve_ball_collision's two states only."""

def mathavan_2014_collision(
    a: BallState,
    b: BallState,
    params: Parameters = ...,
    restitution: _Float = 0.89,
    ball_friction: _Float = 0.05,
    cloth_friction: _Float | None = None,
) -> BallCollisionResult:
    """Mathavan et al. 2014: cloth friction during the impact (default params' mu_s), solved exactly."""

# ------------------------------------------------------------------ tables

class CushionSegment:
    """A straight cushion nose, playing surface on its left; m."""

    @property
    def start(self) -> tuple[float, float]:
        """(x, y), m"""
    @property
    def end(self) -> tuple[float, float]:
        """(x, y), m"""
    @property
    def contact_height(self) -> float:
        """h, m, in (R, 2R)"""
    @property
    def name(self) -> str: ...
    @property
    def inward_normal(self) -> tuple[float, float]:
        """unit normal onto the playing surface"""
    def __init__(self, start: _Vec, end: _Vec, contact_height: _Float, name: str = "") -> None: ...

class JawArc:
    """The rounded cushion tip at a pocket; m."""

    @property
    def centre(self) -> tuple[float, float]:
        """(x, y), m"""
    @property
    def radius(self) -> float:
        """m"""
    @property
    def contact_height(self) -> float:
        """h, m"""
    @property
    def name(self) -> str: ...
    def __init__(self, centre: _Vec, radius: _Float, contact_height: _Float, name: str = "") -> None: ...

class Pocket:
    """A pocket's capture circle; m."""

    @property
    def name(self) -> str: ...
    @property
    def centre(self) -> tuple[float, float]:
        """(x, y), m"""
    @property
    def radius(self) -> float:
        """m"""
    def __init__(self, name: str, centre: _Vec, radius: _Float) -> None: ...

class PocketSpec:
    """One kind of pocket: m, except cut_angle_deg (degrees)."""

    mouth: float
    """m, lip to lip"""
    cut_angle_deg: float
    """degrees, [90, 170]"""
    jaw_radius: float
    """m"""
    shelf: float
    """m"""
    def __init__(self, mouth: _Float, cut_angle_deg: _Float, jaw_radius: _Float, shelf: _Float = 0.0) -> None: ...

class TableSpec:
    """A rectangular table for build_table(); lengths in m."""

    name: str
    length: float
    """m"""
    width: float
    """m"""
    cushion_height: float
    """h, m, in (R, 2R)"""
    ball: BallParameters
    has_pockets: bool
    corner_pockets: PocketSpec
    side_pockets: PocketSpec
    has_diamonds: bool
    diamond_offset: float
    """m"""
    def __init__(
        self,
        name: str,
        length: _Float,
        width: _Float,
        cushion_height: _Float,
        ball: BallParameters,
        has_pockets: bool = True,
        corner_pockets: PocketSpec = ...,
        side_pockets: PocketSpec = ...,
        has_diamonds: bool = True,
        diamond_offset: _Float = 0.0,
    ) -> None: ...

class Table:
    """A table's geometry, read-only and always valid; m. == compares it, pickled as its JSON."""

    def __init__(
        self,
        length: _Float,
        width: _Float,
        cushions: Sequence[CushionSegment],
        ball: BallParameters,
        jaws: Sequence[JawArc] = ...,
        pockets: Sequence[Pocket] = ...,
        diamonds: Sequence[_Vec] = ...,
        name: str = "custom",
    ) -> None: ...
    @staticmethod
    def preset(name: str) -> Table:
        """'pool_9ft', 'snooker_12ft' or 'carom_10ft'."""
    @staticmethod
    def from_spec(spec: TableSpec) -> Table:
        """The geometry of a TableSpec."""
    @staticmethod
    def from_json(text: str) -> Table:
        """A table from its JSON text."""
    def to_json(self) -> str:
        """The full geometry as JSON text."""
    @property
    def name(self) -> str: ...
    @property
    def length(self) -> float:
        """m, along x"""
    @property
    def width(self) -> float:
        """m, along y"""
    @property
    def ball(self) -> BallParameters: ...
    @property
    def cushions(self) -> list[CushionSegment]: ...
    @property
    def jaws(self) -> list[JawArc]: ...
    @property
    def pockets(self) -> list[Pocket]: ...
    @property
    def diamonds(self) -> list[tuple[float, float]]:
        """m"""
    def validate(self) -> None:
        """Checks the geometry (always passes)."""
    def ball_on_table(self, position: _Vec, radius: _Float | None = None) -> bool:
        """A ball (radius m, default the table's) can be placed at position (x, y), m."""
    def inside_playing_area(self, position: _Vec, margin: _Float = 0.0) -> bool:
        """position (x, y), m, is inside the closed playing area or within margin (m) of it."""

TABLE_PRESETS: tuple[str, ...]
"""Names of preset_table(): 'pool_9ft', 'snooker_12ft', 'carom_10ft'."""

def preset_table(name: str) -> Table:
    """Table.preset(name)."""

def pool_table_9ft() -> Table:
    """9-ft pool table (WPA)."""

def snooker_table_12ft() -> Table:
    """Full-size snooker table (WPBSA)."""

def carom_table_10ft() -> Table:
    """UMB match carom table, no pockets."""

def preset_table_spec(name: str) -> TableSpec:
    """The TableSpec of a preset."""

def build_table(spec: TableSpec) -> Table:
    """Table.from_spec(spec)."""

def table_from_json(text: str) -> Table:
    """Table.from_json(text)."""

def table_to_json(table: Table) -> str:
    """table.to_json()."""

# ------------------------------------------------------------------ racks

class PlacedBall:
    """A ball of a rack: id (0 = cue), name, position (x, y) m."""

    id: int
    name: str
    @property
    def position(self) -> tuple[float, float]:
        """(x, y), m"""
    @position.setter
    def position(self, value: _Vec) -> None: ...
    def __init__(self, id: _Int, name: str, position: _Vec) -> None: ...

class RackOptions:
    """gap_sigma (m, [0, 0.005]; 0 frozen) and the seed of the random gaps."""

    gap_sigma: float
    """m"""
    seed: int
    def __init__(self, gap_sigma: _Float = 0.0, seed: _Int = 0) -> None: ...

def rack_nine_ball(table: Table, options: RackOptions = ...) -> list[PlacedBall]:
    """10 balls: cue, 1-9 in a diamond (WPA)."""

def rack_eight_ball(table: Table, options: RackOptions = ...) -> list[PlacedBall]:
    """16 balls: cue, 1-15 in a triangle (WPA)."""

def rack_snooker(table: Table, options: RackOptions = ...) -> list[PlacedBall]:
    """22 balls: cue in the D, 15 reds, the colours on their spots (WPBSA)."""

def foot_spot(table: Table) -> tuple[float, float]:
    """(3L/4, W/2), m."""

def head_string_x(table: Table) -> float:
    """L/4, m."""

class SnookerSpots:
    """Snooker markings scaled to the table, m."""

    @property
    def baulk_line_x(self) -> float: ...
    @property
    def d_radius(self) -> float: ...
    @property
    def black(self) -> tuple[float, float]: ...
    @property
    def pink(self) -> tuple[float, float]: ...
    @property
    def blue(self) -> tuple[float, float]: ...
    @property
    def brown(self) -> tuple[float, float]: ...
    @property
    def yellow(self) -> tuple[float, float]: ...
    @property
    def green(self) -> tuple[float, float]: ...

def snooker_spots(table: Table) -> SnookerSpots:
    """The snooker markings of the table."""

# ------------------------------------------------------------------ scenarios

class SimulationBall:
    """A ball placed for a shot: id, name ('' names it by its id), state before the strike."""

    id: int
    name: str
    state: BallState
    def __init__(
        self,
        id: _Int,
        position: _Vec,
        velocity: _Vec = (0.0, 0.0),
        angular_velocity: _Vec = (0.0, 0.0, 0.0),
        name: str = "",
    ) -> None: ...

class SimulationSettings:
    """Ball and cloth, the cushion model and its constants, the ball-ball model and its constants, the event limit."""

    parameters: Parameters
    cushion_model: str
    """'mathavan_2010' (default), 'han_2005' or 'stronge_compliant'"""
    cushion_restitution: float
    """e_e (mathavan_2010) or e"""
    cushion_friction: float
    """mu_w (mathavan_2010) or mu"""
    cushion_solver: str
    """mathavan_2010's solver: 'exact' or 'paper'"""
    cushion_paper_steps: int
    cushion_exact_tolerance: float
    """mathavan_2010's exact solver: local error per step, [1e-11, 1e-7]"""
    cushion_frequency_ratio: float
    """stronge_compliant's Omega"""
    ball_collision_model: str
    """'coulomb_impulse' (default) or 'mathavan_2014'"""
    ball_collision: BallCollisionParameters
    max_events: int
    def __init__(
        self,
        parameters: Parameters = ...,
        cushion_restitution: _Float | None = None,
        cushion_friction: _Float | None = None,
        ball_collision: BallCollisionParameters | None = None,
        max_events: _Int = 100000,
        cushion_model: str = "mathavan_2010",
        cushion_solver: str = "exact",
        cushion_paper_steps: _Int = 5000,
        cushion_frequency_ratio: _Float | None = None,
        ball_collision_model: str = "coulomb_impulse",
        cushion_exact_tolerance: _Float = 1e-8,
    ) -> None: ...

class ShotStrike:
    """A scenario's cue strike in the scenario's units: m/s, degrees, ball radii (its JSON "cue")."""

    speed: float
    """cue speed, m/s"""
    aim_deg: float
    """degrees anticlockwise from +x"""
    elevation_deg: float
    """degrees"""
    side: float
    """tip offset to the right, ball radii"""
    height: float
    """tip offset above the centre, ball radii"""
    ball: int
    """id of the ball struck"""
    target: int | None
    """id of the ball aimed at (instead of aim_deg)"""
    def __init__(
        self,
        speed: _Float,
        aim_deg: _Float = 0.0,
        elevation_deg: _Float = 0.0,
        side: _Float = 0.0,
        height: _Float = 0.0,
        ball: _Int = 0,
        target: _Int | None = None,
    ) -> None: ...

class Scenario:
    """A shot, read-only and always valid; == compares the full JSON; pickled as its JSON (bit-exact)."""

    def __init__(
        self,
        table: Table | str,
        balls: Iterable[SimulationBall | PlacedBall],
        cue: ShotStrike | None = None,
        *,
        settings: SimulationSettings | None = None,
        cue_parameters: CueParameters | None = None,
        noise: Mapping[str, _Float] | None = None,
    ) -> None: ...
    @staticmethod
    def default() -> Scenario:
        """The built-in 9-ball break."""
    @staticmethod
    def from_json(text: str) -> Scenario:
        """A scenario from its JSON text."""
    @staticmethod
    def from_document(text: str) -> Scenario:
        """A scenario JSON or a result JSON's "scenario"."""
    def to_json(self, indent: _Int = 1) -> str:
        """The scenario in full (indent -1: one line)."""
    def to_dict(self) -> dict[str, Any]:
        """json.loads(to_json())."""
    @property
    def table(self) -> Table: ...
    @property
    def balls(self) -> list[SimulationBall]: ...
    @property
    def cue(self) -> ShotStrike | None:
        """in the scenario's units"""
    @property
    def cue_parameters(self) -> CueParameters: ...
    @property
    def noise(self) -> dict[str, float]:
        """speed m/s, aim_deg, elevation_deg degrees, side, height ball radii"""
    @property
    def settings(self) -> SimulationSettings: ...
    @property
    def parameters(self) -> Parameters: ...

def default_scenario() -> Scenario:
    """The built-in 9-ball break."""

def scenario_from_json(text: str) -> Scenario:
    """Scenario.from_json(text)."""

def scenario_from_document(text: str) -> Scenario:
    """Scenario.from_document(text)."""

def scenario_to_json(scenario: Scenario, indent: _Int = 1) -> str:
    """scenario.to_json(indent)."""

# ------------------------------------------------------------------ whole shots

EVENT_TYPES: tuple[str, ...]
"""Names of the codes in Result.events['type']."""
PHASES: tuple[str, ...]
"""Names of the codes in the 'phase' arrays: 'sliding', 'rolling', 'spinning', 'stationary'."""

class EventArrays(TypedDict):
    """One entry per event, in the order resolved."""

    time: NDArray[np.float64]
    """s"""
    type: NDArray[np.int8]
    """index into EVENT_TYPES"""
    ball: NDArray[np.int32]
    """the ball's id"""
    other: NDArray[np.int32]
    """the other ball's id (ball_ball), else -1"""
    cushion: NDArray[np.int32]
    """index into the table's cushions (ball_cushion), else -1"""
    jaw: NDArray[np.int32]
    """index into the table's jaws (ball_jaw), else -1"""
    pocket: NDArray[np.int32]
    """index into Result.pocket_names (ball_pocket), else -1"""

class BallArrays(TypedDict):
    """One row per ball, in the scenario's order; the final state."""

    id: NDArray[np.int32]
    name: list[str]
    pocketed: NDArray[np.bool_]
    pocket: NDArray[np.int32]
    """index into Result.pocket_names, -1 if not pocketed"""
    pocket_time: NDArray[np.float64]
    """s, NaN if not pocketed"""
    position: NDArray[np.float64]
    """(n, 2), m"""
    velocity: NDArray[np.float64]
    """(n, 2), m/s"""
    angular_velocity: NDArray[np.float64]
    """(n, 3), rad/s"""

class SegmentArrays(TypedDict):
    """One ball's closed-form trajectory, one row per segment (its start)."""

    time: NDArray[np.float64]
    """start, s"""
    position: NDArray[np.float64]
    """(k, 2), m"""
    velocity: NDArray[np.float64]
    """(k, 2), m/s"""
    angular_velocity: NDArray[np.float64]
    """(k, 3), rad/s"""
    phase: NDArray[np.int8]
    """index into PHASES"""

class StateArrays(TypedDict):
    """Every ball's state at each time."""

    time: NDArray[np.float64]
    """(n_times,), s"""
    position: NDArray[np.float64]
    """(n_balls, n_times, 2), m"""
    velocity: NDArray[np.float64]
    """(n_balls, n_times, 2), m/s"""
    angular_velocity: NDArray[np.float64]
    """(n_balls, n_times, 3), rad/s"""
    phase: NDArray[np.int8]
    """(n_balls, n_times), index into PHASES"""

class Result:
    """A simulated shot; arrays built from the library's result on first access."""

    @property
    def end_time(self) -> float:
        """s: every ball at rest or pocketed"""
    @property
    def events(self) -> EventArrays: ...
    @property
    def balls(self) -> BallArrays: ...
    @property
    def segments(self) -> list[SegmentArrays]:
        """per ball, in the scenario's order"""
    @property
    def facts(self) -> dict[str, Any]:
        """what the shot did: the result JSON's "facts" (first contact, contacts, pots, cushions, jaws, ...)"""
    @property
    def scenario(self) -> Scenario:
        """the Scenario that ran: simulate(result.scenario) reproduces this result bit for bit"""
    @property
    def cue_obstructed(self) -> bool:
        """the cue, aligned for the scenario's strike, passes through a ball or below the rail (False without a cue)"""
    @property
    def pocket_names(self) -> list[str]:
        """the table's pockets, indexed by events['pocket'] and balls['pocket']"""
    @property
    def cushion_names(self) -> list[str]:
        """the table's cushions, indexed by events['cushion'] (the result JSON's cushion_name)"""
    @property
    def jaw_names(self) -> list[str]:
        """the table's jaws, indexed by events['jaw'] (the result JSON's jaw_name)"""
    def table_after(self) -> Scenario:
        """The table this shot leaves: balls not pocketed at rest where they stopped, no cue strike."""
    def state_at(self, times: _Float | Sequence[_Float] | NDArray[Any]) -> StateArrays:
        """Every ball at each time (s, finite, >= 0; a number or 1-D); releases the GIL."""
    def sample(self, rate: _Float) -> StateArrays:
        """state_at(k / rate) up to end_time; rate Hz in (0, 1e4], at most 200000 states."""
    def to_dict(self, sample_rate: _Float | None = None) -> dict[str, Any]:
        """The documented result JSON as Python objects (json.loads of `cueball simulate --json`)."""
    def to_json(self, sample_rate: _Float | None = None, indent: _Int = 1) -> str:
        """The documented result JSON text, the CLI's bytes (indent -1: one line)."""
    def to_html(self, sample_rate: _Float | None = None) -> str:
        """The shot as a self-contained HTML viewer page (`cueball simulate --html`'s bytes)."""

def viewer_page(document: str) -> str:
    """The self-contained HTML viewer page with a result's or a game document's JSON filled in."""

def simulate(scenario: _Scenario = None, sample_rate: _Float = 0.0) -> Result:
    """A whole shot until every ball is at rest or pocketed; scenario None is the built-in 9-ball break.

    sample_rate (Hz) is the default of to_dict() and to_json(). Releases the GIL.
    """

# noise= of simulate_batch and simulate_many: True, None or 'scenario' (the scenario's "noise"),
# False or 'none', 'tournament', or a dict of sigmas (speed m/s, aim_deg, elevation_deg, side and
# height ball radii).
_Noise = bool | str | Mapping[str, _Float] | None

def simulate_batch(
    scenario: _Scenario = None, shots: _Int = 1000, threads: _Int = 1, seed: _Int = 0, noise: _Noise = None
) -> dict[str, Any]:
    """Noisy copies of the scenario's shot: json.loads of what `cueball batch --json` prints (one
    writer, batch_result_to_json), pocketed_probability's keys as int ball ids. noise None: the
    scenario's, a UserWarning when it is all zero. Releases the GIL."""

class ManyOutcomes(TypedDict):
    """simulate_many's per-shot outcomes: rows by shot, columns by ball (`ids`)."""

    ids: NDArray[np.int32]
    present: NDArray[np.bool_]
    pocketed: NDArray[np.bool_]
    pocket: NDArray[np.int32]
    final_position: NDArray[np.float64]
    first_contact: NDArray[np.int32]
    cushions_before_contact: NDArray[np.int32]
    cushions: NDArray[np.int32]
    events: NDArray[np.int32]
    miscue: NDArray[np.bool_]
    failure: NDArray[np.bool_]
    speed_reflected: NDArray[np.bool_]
    elevation_reflected: NDArray[np.bool_]
    seconds: float
    shots_per_second: float

def simulate_many(
    scenario: _Scenario,
    actions: NDArray[Any] | Sequence[Sequence[_Float]],
    layouts: NDArray[Any] | None = None,
    threads: _Int = 1,
    seed: _Int = 0,
    noise: _Noise = False,
    first_shot: _Int = 0,
    present: NDArray[np.bool_] | None = None,
) -> ManyOutcomes:
    """N different shots in one call: actions (N, 5) of cue speed m/s, aim deg, elevation deg,
    side and height ball radii (beyond the miscue limit: miscue True, not an error); layouts
    (N, n_balls, 2) m, optional; present (N, n_balls) bool, optional: False leaves the ball off
    that shot's table (final_position NaN, pocket -1). noise False: the actions as given.
    Releases the GIL. first_shot: row of actions[0] in a study split into chunks (its noise,
    its errors' names)."""

def plan_shot(
    scenario: _Scenario,
    target: _Int | None = None,
    *,
    targets: Sequence[_Int] | None = None,
    cue_ball: _Int | None = None,
    pocket: str | _Int = "any",
    kinds: Sequence[str] = ("direct", "bank"),
    noise: str | Mapping[str, _Float] = "tournament",
    seed: _Int = 0,
    simulations: _Int = 4000,
    side: _Float = 0.0,
    height: _Float | None = None,
    position: bool = False,
    next: _Int | None = None,
    next_targets: Sequence[Sequence[_Int]] | None = None,
    next_simulations: _Int = 500,
    in_hand: bool = False,
    region: tuple[_Float, _Float, _Float, _Float] | str | None = None,
    valuation: str = "windows",
    ball_on: _Int | None = None,
    game_ball: _Int | None = None,
) -> dict[str, Any]:
    """The strike that pots ball `target`, or any ball of `targets` (the legal targets; give one of
    the two) (cueball plan-shot): the dict of `plan-shot --json`
    (json.loads of the same writer, plan_to_json: the same keys and values, pairs as lists;
    cue in degrees and ball radii, target (the ball it pots), kind ('direct', 'bank' off one or two cushions, 'kick',
    'combination'), pocket, cushion (only off a cushion), cushions, intermediate_ball, success_probability and its
    standard error, window_probability, aim_window_deg, speed_window m/s, robot, combination_cut_deg (combinations
    only), predicted, alternatives, rejected) and `scenario`, the one key the CLI has not: the Scenario with the
    planned cue (in each alternative too). pocket 'any' (a pot in any pocket counts), 'called' (a call
    shot as in 8-ball and 10-ball: each shot's pot counts only in the pocket it aims at), a pocket's name
    or index. ball_on: the ball the cue ball must meet first (9-ball's and 10-ball's lowest; another
    target is then played only by a combination through it). noise 'tournament', 'none', 'scenario' or a dict of sigmas
    as the scenario's "noise" (speed m/s, aim_deg, elevation_deg, side, height ball radii); raises
    NoFeasibleShot when nothing pots. position=True plays for position (plan-shot --position):
    next_targets: the next shots' legal targets in turn ([[2], [3], ...] for 9-ball, [[9, ..., 15], [8]]
    for 8-ball; instead of next); each shot's dict gains `position` (next, cue_ball, next_feasible, next_success_probability,
    next_kind, next_pocket, next_ball, screened_probability, score). in_hand=True places the cue ball too
    (plan-shot --in-hand; inside region=(x_min, x_max, y_min, y_max) m, or 'kitchen', 'd', 'anywhere', when given): the dict gains
    `in_hand` (cue_ball, spots, spots_played). valuation: how a leave's next shot is valued,
    'windows' (the planner's window search) or 'ghost_ball' (the best straight pot's chance from the
    geometry, no engine run); with position=True or in_hand=True. game_ball: with valuation='ghost_ball', a
    ball whose pot wins at once whichever ball is met first (9-ball's 9; plan-shot --game-ball): a leave is
    also valued by its ghost-ball combination through the next ball. Releases the GIL."""

def _time_run_scenario(scenario: _Scenario = None, repetitions: _Int = 100) -> float:
    """Benchmark hook: seconds per run of the library's run_scenario(), timed in C++."""
