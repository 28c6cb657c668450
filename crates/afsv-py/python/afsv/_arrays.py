"""Array conversion at the boundary: float64 bytes in, numpy views of bytearrays out."""

from __future__ import annotations

import operator
from typing import Any, Optional

import numpy as np


def to_bytes(name: str, x: Any) -> bytes:
    """`x` as native-endian contiguous float64 bytes; a non-numeric or non-1-D `x` is a
    TypeError/ValueError naming the argument."""
    try:
        a = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name}: expected a 1-D array of numbers ({e})") from None
    if a.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D array, got {a.ndim} dimensions")
    return np.ascontiguousarray(a).tobytes()


def maybe_bytes(name: str, x: Any) -> Optional[bytes]:
    """[`to_bytes`] of `x`, or None when `x` is None."""
    return None if x is None else to_bytes(name, x)


def from_bytes(b: bytearray) -> np.ndarray:
    """A writable float64 array over the bytearray the native module returned (no copy)."""
    return np.frombuffer(b, dtype=np.float64)


U64_MAX = 2**64 - 1


def whole(name: str, v: Any, lo: int = 0, hi: int = U64_MAX) -> int:
    """`v` as an int in [lo, hi] (seeds and counts cross as unsigned 64-bit integers): a
    float or a string is a TypeError, a value out of range a ValueError, both naming the
    argument (never an OverflowError, never a silent truncation of 1.5 to 1)."""
    try:
        n = operator.index(v)
    except TypeError:
        raise TypeError(f"{name}: expected an int, got {type(v).__name__}") from None
    if not lo <= n <= hi:
        raise ValueError(f"{name} {n}: must be a whole number from {lo} to {hi}")
    return n
