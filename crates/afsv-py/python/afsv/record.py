"""The result of a run: time and named channels as numpy float64 arrays."""

from __future__ import annotations

import json
from typing import Any, Dict, Iterator, List, Optional, Tuple

import numpy as np

from ._arrays import from_bytes, to_bytes


class Record:
    """A run's channels, named with their unit suffix as in the CLI's CSV records
    (docs/records.md, sign convention afsv-v1), each a 1-D numpy float64 array.

    `rec.t` is the first column (``time_s``, or ``x_m`` for a terrain profile);
    `rec["articulation_deg"]` or `rec.articulation_deg` is a channel; `rec.meta` holds what
    the CLI writes to the sidecar (model, parameters, solver statistics, measures).
    """

    def __init__(self, columns: List[Tuple[str, bytearray]], meta: str) -> None:
        # the numpy view of a channel is made on first use (a sweep that reads two
        # channels of 39 pays for two)
        self._raw: Dict[str, bytearray] = dict(columns)
        self._columns: Dict[str, np.ndarray] = {}
        self._meta_text = meta
        self._meta: Optional[Dict[str, Any]] = None

    @property
    def meta(self) -> Dict[str, Any]:
        """What the CLI writes to the record's sidecar: model, parameters, solver
        statistics, measures (parsed on first use)."""
        if self._meta is None:
            self._meta = json.loads(self._meta_text)
        return self._meta

    @property
    def t(self) -> np.ndarray:
        """The independent variable: the first column (s, or m for a profile)."""
        return self[next(iter(self._raw))]

    @property
    def names(self) -> List[str]:
        """Channel names in record order."""
        return list(self._raw)

    def __getitem__(self, name: str) -> np.ndarray:
        a = self._columns.get(name)
        if a is None:
            try:
                a = self._columns[name] = from_bytes(self._raw[name])
            except KeyError:
                raise KeyError(f"no channel `{name}` (known: {', '.join(self._raw)})") from None
        return a

    def __getattr__(self, name: str) -> np.ndarray:
        if name in self.__dict__.get("_raw", {}):
            return self[name]
        raise AttributeError(name)

    def __contains__(self, name: object) -> bool:
        return name in self._raw

    def __iter__(self) -> Iterator[str]:
        return iter(self._raw)

    def __len__(self) -> int:
        """Number of samples."""
        return len(self.t)

    def __repr__(self) -> str:
        return f"Record({len(self)} samples, {len(self._raw)} channels: {', '.join(self.names[:6])}{', ...' if len(self._raw) > 6 else ''})"

    @classmethod
    def from_arrays(cls, columns: Dict[str, Any], meta: Optional[Dict[str, Any]] = None) -> "Record":
        """A record of your own arrays (e.g. a measurement), channels named with their unit
        suffix as in docs/records.md (``time_s`` first), and the sidecar's metadata (the
        conditions that discovery replays, e.g. ``strut`` and ``excitation``)."""
        cols = []
        n = None
        for name, values in columns.items():
            b = to_bytes(name, values)
            if n is not None and len(b) != n:
                raise ValueError(f"channel `{name}` has {len(b) // 8} samples, the first {n // 8}")
            n = len(b)
            cols.append((str(name), bytearray(b)))
        if not cols:
            raise ValueError("a record needs at least one channel")
        return cls(cols, json.dumps(meta or {}))

    def _native(self, name: str) -> Tuple[str, List[Tuple[str, bytes]], str]:
        """The record as the native module takes it."""
        return name, [(n, bytes(b)) for n, b in self._raw.items()], self._meta_text

    def to_dict(self) -> Dict[str, np.ndarray]:
        """The channels as a dict name -> array (the arrays are shared, not copied)."""
        return {n: self[n] for n in self._raw}

    def to_pandas(self) -> Any:
        """A pandas DataFrame of the channels (pandas is optional: ImportError without it)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError("Record.to_pandas() needs pandas (pip install pandas)") from e
        return pd.DataFrame(self.to_dict())


def read_record(path: Any, *, assume_convention: Optional[str] = None) -> Record:
    """A record file (CSV with its JSON sidecar, docs/records.md) as the CLI reads it: sign
    conventions stated per channel converted to afsv-v1, other units converted, errors with
    line and column. `assume_convention` = ``"afsv-v1"`` accepts a sidecar that states its
    convention in words (after you have checked that they mean afsv-v1)."""
    import os

    from . import _afsv

    cols, meta = _afsv.read_record(os.fspath(path), assume_convention)
    return Record(cols, meta)
