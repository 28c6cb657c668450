"""The result of a run: time and named channels as numpy float64 arrays."""

from __future__ import annotations

import json
from typing import Any, Dict, Iterator, List, Tuple

import numpy as np

from ._arrays import from_bytes


class Record:
    """A run's channels, named with their unit suffix as in the CLI's CSV records
    (docs/records.md, sign convention afsv-v1), each a 1-D numpy float64 array.

    `rec.t` is the first column (``time_s``, or ``x_m`` for a terrain profile);
    `rec["articulation_deg"]` or `rec.articulation_deg` is a channel; `rec.meta` holds what
    the CLI writes to the sidecar (model, parameters, solver statistics, measures).
    """

    def __init__(self, columns: List[Tuple[str, bytearray]], meta: str) -> None:
        self._columns: Dict[str, np.ndarray] = {n: from_bytes(b) for n, b in columns}
        self.meta: Dict[str, Any] = json.loads(meta)

    @property
    def t(self) -> np.ndarray:
        """The independent variable: the first column (s, or m for a profile)."""
        return next(iter(self._columns.values()))

    @property
    def names(self) -> List[str]:
        """Channel names in record order."""
        return list(self._columns)

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"no channel `{name}` (known: {', '.join(self._columns)})") from None

    def __getattr__(self, name: str) -> np.ndarray:
        cols = self.__dict__.get("_columns", {})
        if name in cols:
            return cols[name]
        raise AttributeError(name)

    def __contains__(self, name: object) -> bool:
        return name in self._columns

    def __iter__(self) -> Iterator[str]:
        return iter(self._columns)

    def __len__(self) -> int:
        """Number of samples."""
        return len(self.t)

    def __repr__(self) -> str:
        return f"Record({len(self)} samples, {len(self._columns)} channels: {', '.join(self.names[:6])}{', ...' if len(self._columns) > 6 else ''})"

    def to_dict(self) -> Dict[str, np.ndarray]:
        """The channels as a dict name -> array (the arrays are shared, not copied)."""
        return dict(self._columns)

    def to_pandas(self) -> Any:
        """A pandas DataFrame of the channels (pandas is optional: ImportError without it)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError("Record.to_pandas() needs pandas (pip install pandas)") from e
        return pd.DataFrame(self._columns)
