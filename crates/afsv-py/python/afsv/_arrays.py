"""Array conversion at the boundary: float64 bytes in, numpy views of bytearrays out."""

from __future__ import annotations

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
