"""Type stubs of the native module `afsv._afsv` (crate afsv-py). Arrays cross as bytes of
native-endian float64 in and bytearrays out; structured results as JSON text. Use the
package's Python functions (`afsv.simulate`, ...), which convert to numpy and dicts."""

from typing import Callable, List, Optional, Sequence, Tuple, Union

__version__: str

class SolverError(RuntimeError):
    """A run diverged: `t` (s), `state` (floats, or name -> SI value), `reason`."""

    t: float
    state: Union[List[float], dict[str, float], None]
    reason: str

DescRef = Tuple[str, str, str]
Columns = List[Tuple[str, bytearray]]

def synthesize_terrain(
    iso_class: Optional[str],
    terrain: Optional[str],
    alpha: Optional[float],
    waviness: Optional[float],
    band: Tuple[float, float],
    coherence: str,
    half_track: Optional[float],
    speed: Optional[float],
    length: float,
    dx: float,
    seed: int,
) -> Tuple[Columns, str]: ...
def welch(
    x: bytes, dx: float, segment_m: Optional[float], overlap: float, window: str, detrend: str
) -> Tuple[bytearray, bytearray, str]: ...
def cross(
    x: bytes, y: bytes, dx: float, segment_m: Optional[float], overlap: float, window: str, detrend: str
) -> Tuple[bytearray, bytearray, bytearray, bytearray, bytearray, bytearray]: ...
def simulate_yaw(
    vehicle: Optional[DescRef],
    params_json: Optional[str],
    load: str,
    speed_kmh: float,
    input: str,
    table_t: Optional[bytes],
    table_deg: Optional[bytes],
    input_time: float,
    duration: float,
    dt: float,
    solver: str,
    rtol: float,
    form: str,
    rk4_step: float,
) -> Tuple[Columns, str]: ...
def simulate_yaw_batch(jobs: List[dict]) -> List[Tuple[Columns, str]]: ...
def simulate_strut(
    strut: str, freq: float, amp_mm: float, cycles: float, gamma0: Optional[float], rate: float, solver: str
) -> Tuple[Columns, str]: ...
def characterize_strut(strut: str, gamma0: Optional[float]) -> str: ...
def simulate_truck(
    vehicle: Optional[DescRef],
    truck: str,
    cg_height_m: Optional[float],
    ramp_rate: Optional[float],
    no_bump_stops: bool,
    direction: str,
    terrain_class: Optional[str],
    waviness: float,
    band: Tuple[float, float],
    mc: float,
    seed: int,
    duration: Optional[float],
    dt: float,
    sp_threshold: Optional[float],
    sp_max_dip: Optional[float],
) -> Tuple[Columns, str]: ...
def simulate_vehicle(
    vehicle: Optional[DescRef],
    load: str,
    speed_kmh: float,
    terrain_class: Optional[str],
    mc: float,
    seed: int,
    hps: Optional[str],
    steer_kind: str,
    steer_values: Sequence[float],
    duration: float,
    dt: float,
) -> Tuple[Columns, str]: ...
def wbv(
    t: bytes,
    ax: Optional[bytes],
    ay: Optional[bytes],
    az: Optional[bytes],
    hours: float,
    weightings: Tuple[str, str, str],
    k: Tuple[float, float, float],
    method: str,
) -> str: ...
def ltr(fz_lf: bytes, fz_rf: bytes, fz_lr: bytes, fz_rr: bytes) -> bytearray: ...
def roll_measures(
    t: bytes,
    ltr: bytes,
    lateral_accel: bytes,
    drt_threshold: float,
    sp_threshold: float,
    sp_max_dip: float,
    sp_min_duration: float,
) -> str: ...
def decay(t: bytes, y: bytes, start_s: Optional[float], end_s: Optional[float]) -> str: ...
def step(
    t: bytes, u: bytes, y: bytes, t_step: Optional[float], amplitude: Optional[float], settle_fraction: float
) -> str: ...
def describe_vehicle(kind: str, value: str, folder: str) -> str: ...
def builtin_vehicles() -> List[Tuple[str, str]]: ...
def minimize(
    fun: Callable[[List[float]], object],
    lower: Sequence[float],
    upper: Sequence[float],
    n_constraints: int,
    method: str,
    x0: Optional[Sequence[float]],
    options_json: Optional[str],
) -> str: ...
def evaluate(vehicle: Optional[DescRef], seed: int, seeds: int, speed_kmh: float) -> str: ...

class AfsProblem:
    """The Chapter 4 frame-steering design problem (Eq 4.8 with the Eq 4.17 weights; Eq 4.10
    and a minimum full-lock arm as constraints)."""

    def __init__(
        self, relaxed: bool = False, min_arm_m: Optional[float] = 0.25, rtol: float = 1e-8, form: str = "energy-consistent"
    ) -> None: ...
    @property
    def bounds(self) -> Tuple[List[float], List[float]]: ...
    @property
    def n_constraints(self) -> int: ...
    @property
    def variables(self) -> List[str]: ...
    def current(self) -> List[float]: ...
    def __call__(self, x: Sequence[float]) -> Tuple[float, List[float]]: ...

def optimize_afs(
    relaxed: bool,
    min_arm_m: Optional[float],
    starts: int,
    seed: int,
    search_points: int,
    screen_mesh: float,
    min_mesh: float,
    sqp_calls: int,
    rtol: float,
    form: str,
) -> str: ...
def optimize_hps(
    vehicle: Optional[DescRef],
    population: int,
    generations: int,
    seed: int,
    terrain_seed: int,
    reevaluation_seeds: int,
    roll: bool,
    speed_sweep: bool,
) -> str:
    """The Chapter 6 HPS design GA of `afsv optimize hps` (Eqs 6.19-6.20, Table 6.4): the
    CLI's JSON plus `strut_json` (the --strut-out text) and `speed_sweep` (D4, or null)."""
    ...
def read_record(path: str, assume_convention: Optional[str]) -> Tuple[Columns, str]: ...
def discover_effects(
    model: str,
    train: List[Tuple[str, List[Tuple[str, bytes]], str]],
    holdout: List[Tuple[str, List[Tuple[str, bytes]], str]],
    effects: Optional[List[str]],
    max_effects: int,
) -> str: ...
