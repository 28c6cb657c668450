"""Two-track terrain synthesis and spectral estimates (crate ``terrain-psd``), as
``afsv terrain generate`` and ``afsv terrain psd``."""

from __future__ import annotations

import json
from typing import Any, Dict, NamedTuple, Optional, Tuple

import numpy as np

from . import _afsv
from ._arrays import from_bytes, to_bytes, whole
from .record import Record


def synthesize(
    *,
    iso_class: Optional[str] = None,
    terrain: Optional[str] = None,
    alpha: Optional[float] = None,
    waviness: Optional[float] = None,
    band: Tuple[float, float] = (0.02, 5.0),
    coherence: str = "piecewise:0.3",
    half_track: Optional[float] = None,
    speed: Optional[float] = None,
    length: float = 100.0,
    dx: float = 0.05,
    seed: int = 1,
) -> Record:
    """Left and right track profiles whose PSD is G_d(n) = alpha_r n^-w (Eq 2.8) on `band`
    (cycles/m) and whose coherence follows `coherence` (``piecewise:M_C``, Eq 2.10/6.5;
    ``bogsjo:RHO``, Eq 1.9, with `half_track`; ``zhang``, Eq 1.8, with `speed`; ``full``;
    ``none``), by random-phase synthesis: columns ``x_m``, ``left_m``, ``right_m``.

    Choose the PSD with one of `iso_class` (ISO 8608 A-H, default E), `terrain`
    (forestry, pasture, mvee, plowed; Tables 1.2/2.4) or `alpha` with `waviness`. The same
    seed gives the same profile as ``afsv terrain generate --seed``."""
    cols, meta = _afsv.synthesize_terrain(
        iso_class, terrain,
        None if alpha is None else float(alpha),
        None if waviness is None else float(waviness),
        (float(band[0]), float(band[1])), coherence,
        None if half_track is None else float(half_track),
        None if speed is None else float(speed),
        float(length), float(dx), whole("seed", seed),
    )
    return Record(cols, meta)


class Spectrum(NamedTuple):
    """A one-sided Welch PSD: frequencies (cycles per unit of `dx`), density (unit^2 per
    frequency unit) and the estimate's settings."""

    freq: np.ndarray
    psd: np.ndarray
    info: Dict[str, Any]


def welch_psd(
    x: Any,
    dx: float,
    *,
    segment_m: Optional[float] = None,
    overlap: float = 0.5,
    window: str = "hann",
    detrend: str = "mean",
) -> Spectrum:
    """Welch one-sided PSD of the uniformly sampled signal `x` (spacing `dx`). Default
    segment: the largest power-of-two number of samples <= 1/8 of the record."""
    f, p, info = _afsv.welch(to_bytes("x", x), float(dx), None if segment_m is None else float(segment_m), float(overlap), window, detrend)
    return Spectrum(from_bytes(f), from_bytes(p), json.loads(info))


class CrossSpectrum(NamedTuple):
    """Welch cross-spectral estimates of two signals: PSDs, the cross-spectral density
    conj(X) Y and the magnitude-squared coherence (Eq 2.9)."""

    freq: np.ndarray
    pxx: np.ndarray
    pyy: np.ndarray
    csd_re: np.ndarray
    csd_im: np.ndarray
    coherence: np.ndarray


def cross_spectrum(
    x: Any,
    y: Any,
    dx: float,
    *,
    segment_m: Optional[float] = None,
    overlap: float = 0.5,
    window: str = "hann",
    detrend: str = "mean",
) -> CrossSpectrum:
    """Welch PSDs, cross-spectrum and coherence (Eq 2.9) of two tracks."""
    parts = _afsv.cross(to_bytes("x", x), to_bytes("y", y), float(dx), None if segment_m is None else float(segment_m), float(overlap), window, detrend)
    return CrossSpectrum(*(from_bytes(b) for b in parts))
