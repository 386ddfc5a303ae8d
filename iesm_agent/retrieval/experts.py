"""Expert plugins: declarative specs loaded from TOML files and entry points.

Sources, later ones overriding earlier ones by name: the shipped `experts/` folder, Python
entry points of group `iesm_agent.experts` (resolving to an `ExpertSpec`, a dict or the path of
a TOML file), then the user directories in the order given. Adding an expert needs no code.
"""

from __future__ import annotations

from collections.abc import Iterable
from importlib.metadata import entry_points
from pathlib import Path
from typing import Any

import tomllib
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from ..errors import IesmError
from ..resources import resource_dir
from ..store.mapstore import VIEW_FIELDS

ENTRY_POINT_GROUP = "iesm_agent.experts"


class ExpertSpec(BaseModel):
    """One expert: `fields` are the candidate fields its prompt sees (`id` is always added)."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    name: str = Field(pattern=r"^[A-Za-z0-9_-]+$")
    title: str
    gate_description: str
    focus: str
    fields: tuple[str, ...]
    template: str = "expert.j2"

    @field_validator("fields")
    @classmethod
    def _known_fields(cls, fields: tuple[str, ...]) -> tuple[str, ...]:
        unknown = [f for f in fields if f not in VIEW_FIELDS]
        if unknown:
            raise ValueError(f"unknown candidate field(s) {unknown}; allowed: {list(VIEW_FIELDS)}")
        return ("id",) + tuple(f for f in dict.fromkeys(fields) if f != "id")


def _validate(data: Any, source: str) -> ExpertSpec:
    try:
        return ExpertSpec.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        where = ".".join(str(p) for p in err["loc"]) or None
        raise IesmError(f"invalid expert spec: {err['msg']}", source, where) from exc


def load_spec(path: str | Path) -> ExpertSpec:
    """Read one expert spec from a TOML file; errors name the file and the field."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise IesmError(f"cannot read expert spec: {exc}", path) from exc
    return _validate(data, str(path))


def _from_dir(directory: Path) -> list[ExpertSpec]:
    if not directory.is_dir():
        raise IesmError("expert directory does not exist", directory)
    return [load_spec(p) for p in sorted(directory.glob("*.toml"))]


def _from_entry_points() -> list[ExpertSpec]:
    specs = []
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        source = f"entry point {ep.name} ({ep.value})"
        try:
            obj = ep.load()
        except Exception as exc:  # a broken plugin names itself instead of crashing blindly
            raise IesmError(f"cannot load expert plugin: {exc}", source) from exc
        if isinstance(obj, ExpertSpec):
            specs.append(obj)
        elif isinstance(obj, (str, Path)):
            specs.append(load_spec(obj))
        else:
            specs.append(_validate(obj, source))
    return specs


def load_experts(dirs: Iterable[str | Path] = (), *, plugins: bool = True) -> dict[str, ExpertSpec]:
    """All experts by name, in load order (shipped, entry points, `dirs`); later override earlier."""
    specs = _from_dir(resource_dir("experts"))
    if plugins:
        specs += _from_entry_points()
    for d in dirs:
        specs += _from_dir(Path(d))
    registry: dict[str, ExpertSpec] = {}
    for spec in specs:
        registry[spec.name] = spec  # an override keeps the position of the first definition
    return registry
