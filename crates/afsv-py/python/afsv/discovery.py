"""Model-discrepancy discovery on in-memory records (crate ``afsv-discovery``,
docs/discovery.md), as ``afsv discover``."""

from __future__ import annotations

import json
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

from . import _afsv
from ._arrays import whole
from .record import Record

Records = Union[Mapping[str, Record], Sequence[Record]]


def _named(records: Records, what: str) -> List[Any]:
    items = records.items() if isinstance(records, Mapping) else ((f"{what}_{i:02d}", r) for i, r in enumerate(records))
    out = []
    for name, r in items:
        if not isinstance(r, Record):
            raise TypeError(f"{what}: expected Records, got {type(r).__name__}")
        out.append(r._native(str(name)))
    if not out:
        raise ValueError(f"{what}: no record")
    return out


def discover(
    model: str,
    train: Records,
    holdout: Records,
    *,
    effects: Optional[Sequence[str]] = None,
    max_effects: int = 4,
) -> Dict[str, Any]:
    """Which physical effect does the paper's model lack? `model`: ``hps-strut`` (Chapter
    5) or ``yaw-plane`` (Chapter 3), nominal parameters. Calibrates on the `train` records,
    tries the model's catalogue of missing effects (`effects`: only these), names at most
    `max_effects` significant ones, and measures the gap shrink on the `holdout` records.
    Records are :class:`Record` objects (a dict gives their names), e.g. from
    :func:`read_record` or :meth:`Record.from_arrays`, with the conditions in their
    metadata. Returns what ``afsv discover`` prints: ``outcome``, ``named``,
    ``effect_params``, ``gap_shrink``, per-channel errors, ``exit_code`` (0 named, 3 a
    model-form discrepancy, 4 nothing missing)."""
    return json.loads(_afsv.discover_effects(
        model, _named(train, "train"), _named(holdout, "holdout"),
        None if effects is None else [str(e) for e in effects], whole("max_effects", max_effects),
    ))
