"""afsv: articulated frame-steered vehicles from Python.

Terrain synthesis and spectra, the yaw-plane model (Chapter 3), the hydro-pneumatic strut
(Chapter 5), the rigid truck (Chapter 2) and the 3-D vehicle (Chapter 6), the measures,
vehicle descriptions and the optimisers of the ``afsv`` toolkit, with numpy arrays in and
out. Every run is the Rust library's, with the GIL released; see docs/python.md.
"""

from ._afsv import SolverError, __version__
from .discovery import discover
from .evaluate import evaluate
from .hps import HpsAssessment, HpsDesign, HpsGaSettings, HpsOptimum, RideValues, Spread, optimize_hps
from .measures import decay, iso2631, ltr, roll_measures, step
from .models import (
    characterize_strut,
    simulate,
    simulate_strut,
    simulate_truck,
    simulate_vehicle,
    simulate_yaw,
    simulate_yaw_batch,
)
from .optimize import AfsProblem, OptimizeResult, minimize, optimize_afs
from .record import Record, read_record
from .terrain import CrossSpectrum, Spectrum, cross_spectrum, synthesize, welch_psd
from .vehicle import Vehicle, builtin_vehicles, load_vehicle

__all__ = [
    "SolverError",
    "__version__",
    "Record",
    "Vehicle",
    "load_vehicle",
    "builtin_vehicles",
    "synthesize",
    "welch_psd",
    "cross_spectrum",
    "Spectrum",
    "CrossSpectrum",
    "simulate",
    "simulate_yaw",
    "simulate_yaw_batch",
    "simulate_strut",
    "characterize_strut",
    "simulate_truck",
    "simulate_vehicle",
    "iso2631",
    "ltr",
    "roll_measures",
    "decay",
    "step",
    "minimize",
    "evaluate",
    "AfsProblem",
    "optimize_afs",
    "optimize_hps",
    "HpsOptimum",
    "HpsDesign",
    "HpsGaSettings",
    "HpsAssessment",
    "RideValues",
    "Spread",
    "read_record",
    "discover",
    "OptimizeResult",
]
