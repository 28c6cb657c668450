"""Vehicle descriptions: the TOML files (format ``afsv-vehicle-1``, docs/vehicles.md) that
every ``--vehicle`` option of the CLI reads, and the built-in ``prototype`` (Chapter 6,
Tables 3.1 and 6.1-6.3) and ``chapter2-truck`` (Tables 2.1-2.3)."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Optional, Tuple, Union

from . import _afsv

PathLike = Union[str, "os.PathLike[str]"]


class Vehicle:
    """A checked vehicle description.

    Make one with :func:`load_vehicle` (a file or a built-in name) or
    :meth:`Vehicle.from_toml`; `save` writes the same TOML the CLI reads. `params` holds
    the parameter sets it converts to (the 3-D vehicle's, the yaw-plane model's per load
    case, the steering's and strut's; or the truck's), as ``afsv params dump`` writes them.
    """

    def __init__(self, ref: Tuple[str, str, str]) -> None:
        self._ref = ref
        info = json.loads(_afsv.describe_vehicle(*ref))
        self.name: str = info["name"]
        self.kind: str = info["kind"]
        self.toml: str = info["toml"]
        self.params: Dict[str, Any] = info["params"]

    @classmethod
    def from_toml(cls, text: str, folder: PathLike = ".") -> "Vehicle":
        """A description from TOML text; relative strut files are read from `folder`."""
        return cls(("text", text, os.fspath(folder)))

    def save(self, path: PathLike) -> None:
        """Write the description as TOML (what ``--vehicle FILE`` and `load_vehicle` read)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.toml)

    @property
    def ref(self) -> Tuple[str, str, str]:
        """How the native module names this description."""
        return self._ref

    def __repr__(self) -> str:
        return f"Vehicle({self.name!r}, {self.kind})"


def load_vehicle(source: PathLike) -> Vehicle:
    """The description in the file `source`, or the built-in of that name (a file of that
    name wins, as on the command line). Errors name file, line, column and field path."""
    s = os.fspath(source)
    if not os.path.exists(s) and s in dict(_afsv.builtin_vehicles()):
        return Vehicle(("builtin", s, "."))
    return Vehicle(("file", s, "."))


def builtin_vehicles() -> List[Tuple[str, str]]:
    """The built-in descriptions: (name, what it is)."""
    return list(_afsv.builtin_vehicles())


def vehicle_ref(v: Union[None, str, "os.PathLike[str]", Vehicle]) -> Optional[Tuple[str, str, str]]:
    """The native reference of a vehicle argument (None: the model's default)."""
    if v is None:
        return None
    if isinstance(v, Vehicle):
        return v.ref
    if isinstance(v, (str, os.PathLike)):
        return load_vehicle(v).ref
    raise TypeError(f"vehicle: expected a Vehicle, a file or a built-in name, got {type(v).__name__}")
