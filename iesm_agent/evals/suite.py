"""Query suites: JSONL, one `SuiteQuery` per line, validated against the maps they name.

`map` is a path relative to the suite file or an absolute path (a `.iesm` map, or a JSON map the
importers read, such as the paper's `scene_*_caption.json`), or the name of a shipped map
(`apartment`). Errors name the suite file and line number.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Iterable, Optional

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from ..errors import IesmError
from ..fileio import load_json, read_text, write_text
from ..store.model import Id, Metres, SceneMap
from ..store.refs import open_map, resolve_map_path

#: a query type is a free short label; the paper's five (o, or, od, ord, ard) keep their meaning and
#: order in reports, any other label (e.g. "s" for spatial) gets its own column after them
QueryType = Annotated[str, Field(min_length=1, max_length=24, pattern=r"^[A-Za-z0-9_.,\-]+$")]


class SuiteQuery(BaseModel):
    """One query: the instance `target` it was written for and the ids `accept`ed as correct."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    id: str = Field(min_length=1)
    map: str = Field(min_length=1)
    query: str = Field(min_length=1)
    type: Optional[QueryType] = None
    target: Id
    accept: list[Id] = Field(default_factory=list, max_length=10_000)
    start: Optional[tuple[Metres, Metres]] = None  # (x, y) m: the robot's start for N-SR
    #: paraphrase group: lines with the same group are wordings of one intent
    group: Optional[str] = Field(default=None, min_length=1, max_length=200)

    @model_validator(mode="after")
    def _target_accepted(self) -> "SuiteQuery":
        if self.target not in self.accept:
            self.accept = [self.target, *self.accept]
        return self


class MapRegistry:
    """Loads each map file once (by resolved path); a map that fails to load fails once, and
    every later `get` re-raises the same error without reading the file again."""

    def __init__(self) -> None:
        self._maps: dict[Path, SceneMap | IesmError] = {}
        self._ids: dict[Path, frozenset[int]] = {}

    def get(self, path: Path) -> SceneMap:
        if path not in self._maps:
            try:
                self._maps[path] = open_map(path)
            except IesmError as exc:
                self._maps[path] = exc
        found = self._maps[path]
        if isinstance(found, IesmError):
            raise found
        return found

    def ids(self, path: Path) -> frozenset[int]:
        """The instance ids of the map at `path` (computed once per map)."""
        if path not in self._ids:
            self._ids[path] = frozenset(inst.id for inst in self.get(path).instances)
        return self._ids[path]


@dataclass
class SuiteEntry:
    """A validated query with where it came from and the map file it resolves to."""

    query: SuiteQuery
    source: Path
    line: int
    map_path: Path


@dataclass
class Suite:
    entries: list[SuiteEntry] = field(default_factory=list)
    errors: list[IesmError] = field(default_factory=list)


def _check(query: SuiteQuery, path: Path, registry: MapRegistry) -> Path:
    """Resolved map path of `query`; raises ValueError when its map or ids are unknown."""
    try:
        map_path = resolve_map_path(query.map, path.parent)
        ids = registry.ids(map_path)
    except IesmError as exc:  # an unknown or unusable map is this line's problem
        raise ValueError(str(exc) if exc.source else exc.message) from exc
    unknown = [i for i in query.accept if i not in ids]
    if unknown:
        which = "target" if query.target in unknown else "accept id"
        raise ValueError(f"{which} {unknown[0]} is not an instance of map {query.map!r}")
    return map_path


def load_suites(paths: Iterable[str | Path], *, skip_invalid: bool = False,
                registry: MapRegistry | None = None) -> Suite:
    """Parse and validate suites. Each bad line raises an `IesmError` naming file and line, or
    with `skip_invalid` is collected in `Suite.errors` and left out. Query ids are unique across
    all suites given."""
    registry = registry or MapRegistry()
    suite = Suite()
    seen: dict[str, str] = {}
    paths = [Path(p) for p in paths]
    for path in paths:
        try:  # a regular UTF-8 file of bounded size (a FIFO or /dev/zero is refused, not read)
            text = read_text(path)
        except IesmError as exc:
            raise IesmError(f"cannot read suite: {exc.message}", path) from None
        for number, line in enumerate(text.split("\n"), start=1):  # JSON Lines: U+2028 / U+0085 are text
            if not line.strip():
                continue
            try:
                query = SuiteQuery.model_validate(load_json(line, path, f"line {number}"))
                if query.id in seen:
                    raise ValueError(f"duplicate query id {query.id!r} (first at {seen[query.id]})")
                map_path = _check(query, path, registry)
            except ValidationError as exc:
                err = exc.errors()[0]
                loc = ".".join(str(p) for p in err["loc"])
                error = IesmError(f"{loc}: {err['msg']}" if loc else err["msg"], path, f"line {number}")
            except ValueError as exc:
                error = IesmError(str(exc), path, f"line {number}")
            except IesmError as exc:  # not JSON, or too large or deep
                error = exc
            else:
                seen[query.id] = f"{path}:{number}"
                suite.entries.append(SuiteEntry(query, path, number, map_path))
                continue
            if not skip_invalid:
                raise error
            suite.errors.append(error)
    if not suite.entries:
        what = f"no valid query ({len(suite.errors)} invalid lines)" if suite.errors else "no query"
        raise IesmError(f"the suites hold {what}", ", ".join(map(str, paths)) or None, "suite")
    return suite


def write_suite(queries: Iterable[SuiteQuery], path: str | Path) -> None:
    """Write `queries` as JSONL atomically (temporary file + rename)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, "".join(json.dumps(q.model_dump(mode="json", exclude_none=True)) + "\n" for q in queries))
