"""Performance measures on numpy arrays (crate ``perf-measures``), as
``afsv measures wbv|decay|step``: ISO 2631-1 whole-body vibration (Eq 1.1), LTR (Eq 2.11)
with the DRT and SP-DRT of section 2.3, free-decay fits and step metrics."""

from __future__ import annotations

import json
from typing import Any, Dict, Optional, Tuple

import numpy as np

from . import _afsv
from ._arrays import from_bytes, maybe_bytes, to_bytes


def iso2631(
    t: Any,
    *,
    ax: Any = None,
    ay: Any = None,
    az: Any = None,
    hours: float = 8.0,
    weightings: Tuple[str, str, str] = ("wd", "wd", "wk"),
    k: Tuple[float, float, float] = (1.4, 1.4, 1.0),
    method: str = "fft",
) -> Dict[str, Any]:
    """ISO 2631-1 whole-body vibration of seat accelerations (m/s², unweighted) sampled at
    the uniform times `t` (s): per-axis weighted RMS a_w, crest factor, MTVV, VDV, the
    combined a_v = sqrt(sum k_i² a_wi²) (Eq 1.1), A(8) for `hours` and the Annex B health
    guidance caution zone. Defaults: seat-pan health weightings (W_d, W_d, W_k) and
    k = 1.4, 1.4, 1. `method`: ``fft`` (exact analog response) or ``iir``."""
    w = tuple(str(s) for s in weightings)
    kk = tuple(float(v) for v in k)
    if len(w) != 3 or len(kk) != 3:
        raise ValueError("weightings and k: expected three values (x, y, z)")
    return json.loads(_afsv.wbv(
        to_bytes("t", t), maybe_bytes("ax", ax), maybe_bytes("ay", ay), maybe_bytes("az", az),
        float(hours), w, kk, method,
    ))


def ltr(fz_lf: Any, fz_rf: Any, fz_lr: Any, fz_rr: Any) -> np.ndarray:
    """Lateral load transfer ratio per sample of a two-axle vehicle (Eq 2.11):
    |sum(F_zL - F_zR)| / sum(F_zL + F_zR), tire normal forces in N (a lifted tire counts 0)."""
    return from_bytes(_afsv.ltr(to_bytes("fz_lf", fz_lf), to_bytes("fz_rf", fz_rf), to_bytes("fz_lr", fz_lr), to_bytes("fz_rr", fz_rr)))


def roll_measures(
    t: Any,
    ltr: Any,
    lateral_accel: Any,
    *,
    drt_threshold: float = 0.999,
    sp_threshold: float = 0.95,
    sp_max_dip: float = 0.5,
    sp_min_duration: float = 1.0,
) -> Dict[str, Any]:
    """Smooth-road DRT (lateral acceleration when the LTR first reaches `drt_threshold`)
    and the sustained period of near-unity LTR with its SP-DRT (RMS lateral acceleration
    over the period; section 2.3). A measure not found is None with a ``*_reason``."""
    return json.loads(_afsv.roll_measures(
        to_bytes("t", t), to_bytes("ltr", ltr), to_bytes("lateral_accel", lateral_accel),
        float(drt_threshold), float(sp_threshold), float(sp_max_dip), float(sp_min_duration),
    ))


def decay(t: Any, y: Any, *, start_s: Optional[float] = None, end_s: Optional[float] = None) -> Dict[str, Any]:
    """Fit y = c + A exp(-zeta wn t) cos(wd t + phi) (a single-DOF free decay, e.g. the
    articulation after a steering pulse, section 3.3): natural frequency (Hz), damping
    ratio and fit quality. The fit starts at `start_s` or at the largest deviation from the
    final value."""
    return json.loads(_afsv.decay(to_bytes("t", t), to_bytes("y", y), None if start_s is None else float(start_s), None if end_s is None else float(end_s)))


def step(
    t: Any,
    u: Any,
    y: Any,
    *,
    t_step: Optional[float] = None,
    amplitude: Optional[float] = None,
    settle_fraction: float = 0.1,
) -> Dict[str, Any]:
    """Step-response metrics of `y` to a step in `u` (section 3.3): steady gain, 0-100 %
    rise time, percent overshoot and peak. The step time and amplitude are found from `u`
    unless given."""
    return json.loads(_afsv.step(
        to_bytes("t", t), to_bytes("u", u), to_bytes("y", y),
        None if t_step is None else float(t_step), None if amplitude is None else float(amplitude),
        float(settle_fraction),
    ))
