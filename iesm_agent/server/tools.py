"""The assistant-facing tools over a set of served maps, defined once.

`MapService.tools()` is the single definition behind every surface: the MCP server registers
these functions, `iesm tools` prints `tool_specs()` of them, and each store tool is generated from
the `MapStore` method of the same name (`mapstore.TOOLS`, so store tools added there appear here
without edits) with one extra optional `map` argument. Schemas come from `store.tools.function_schema`,
the function behind `MapStore.tool_specs()`.

All tools are coroutines run on the server's event loop: the maps, the retrievers and their
caches are only ever touched from that one thread, so they need no locks. Model calls that
compute locally (the offline model, with its sentence embeddings) run on a bounded pool of worker
threads (`workers.WorkerPool`, one per core) so the loop stays free; a remote model's I/O
overlaps on the loop because `Retriever.aask` awaits it.
"""

from __future__ import annotations

import asyncio
import functools
import importlib.util
import inspect
import sys
import types
import typing
from typing import Any, Callable, Literal, Optional

from pydantic import BaseModel, ConfigDict, ValidationError, create_model

from ..errors import IesmError
from ..store import MapStore
from ..store import mapstore as mapstore_module
from ..store.model import Id, Metres
from ..store.tools import function_schema
from .batching import ParseBatcher
from .results import FindGoalResult, Ranked, argument_problem, place
from .workers import OffLoopModel, WorkerPool, new_query

#: longest query (or other text argument) a tool accepts, in characters
#: the longest text argument a map tool accepts, in characters
MAX_ARGUMENT_CHARS = 2000
#: ids of the top of the fused ranking find_goal reports
RANKING_SHOWN = 5
SPEC_FORMATS = ("json", "openai", "mcp")
#: answered once per map at start-up: a descriptive one, so the offline model's embedding path is
#: warm too, and one that names no kind, so its reading of uses by meaning is
WARM_UP_QUERIES = ("a cosy blue wooden seat for reading near the window in the living room",
                   "somewhere to put my feet up with a book")
_MAP_ARG_DOC = "\n\nArgs:\n    map: the served map's name (scene id; default: the first map)"


class MapService:
    """The served maps and the warm retrievers over them.

    `maps` maps a name (the map's scene id) to its `MapStore`; the first is the default.
    `providers` lists the model specs callers may pick (the first is the default): a caller
    cannot make the server spend another endpoint's credentials. `workers`: threads computing
    local model calls (default: the cores)."""

    def __init__(self, maps: dict[str, MapStore] | None = None, providers: tuple[str, ...] = ("offline",),
                 workers: int | None = None):
        if not providers:
            raise IesmError("at least one provider is required", None, "providers")
        self.maps = dict(maps or {})
        self.providers = tuple(providers)
        self.pool = WorkerPool(workers)
        self._slots: tuple[asyncio.AbstractEventLoop, asyncio.Semaphore] | None = None
        self._retrievers: dict[tuple[str, str, str], Any] = {}
        self._planners: dict[str, Any] = {}
        self._tools: list[Callable[..., Any]] | None = None
        self._parses = ParseBatcher()  # queries arriving together are parsed together

    @classmethod
    def open(cls, refs: list[str], providers: tuple[str, ...] = ("offline",)) -> "MapService":
        """Load the maps `refs` name (`.iesm` files, importable JSON or shipped names)."""
        from ..store import open_map

        maps: dict[str, MapStore] = {}
        for ref in refs:
            store = MapStore(open_map(ref))
            name = store.scene.scene_id
            if name in maps:
                raise IesmError(f"two maps share the scene id {name!r}", ref)
            maps[name] = store
        return cls(maps, providers)

    # ------------------------------------------------------------------ state
    def store(self, map: Optional[str] = None) -> MapStore:
        """The `MapStore` named `map` (None: the first served map)."""
        if not self.maps:
            raise IesmError("no map is served", None, "map")
        if map is None or map == "":
            return next(iter(self.maps.values()))
        try:
            return self.maps[map]
        except KeyError:
            raise IesmError(f"unknown map {map!r}; served: {', '.join(self.maps)}", None, "map") from None

    def retriever(self, map: Optional[str], method: str, provider: Optional[str]):
        """The warm `Retriever` for (map, method, provider), built on first use and kept."""
        from ..retrieval import Retriever

        store = self.store(map)
        provider = provider or self.providers[0]
        if provider not in self.providers:
            raise IesmError(f"provider {provider!r} is not enabled on this server; enabled: "
                            f"{', '.join(self.providers)}", None, "provider")
        key = (store.scene.scene_id, method.strip(), provider)
        if key in self._retrievers:
            return self._retrievers[key]
        # remote answers go to the response cache, as with `iesm ask`
        fresh = Retriever(store, provider=provider, method=method, cache=True)
        if not fresh.model.cacheable:  # answers locally: compute on the worker pool
            fresh.model = OffLoopModel(fresh.model, self.pool)
        # kept under the normalised method ("experts: obj,obj" -> "experts:obj"): a bounded set
        return self._retrievers.setdefault((key[0], fresh.method, provider), fresh)

    async def warm_up(self) -> None:
        """Load the embedding model (when installed; saying so on stderr, with the time it took),
        answer a descriptive query per map with the default provider and build the planning
        grids, so that the first caller pays no start-up cost. A failing warm-up query (a dead
        endpoint) is reported on stderr, not raised."""
        from ..embeddings import encoder_name, get_encoder, load_seconds

        if encoder_name() is not None:
            print(f"iesm serve: loading the sentence encoder {encoder_name()} ...", file=sys.stderr, flush=True)
            encoder = await self.pool.run(get_encoder)
            print(f"iesm serve: sentence encoder {'loaded' if encoder else 'unavailable'} in {load_seconds():.1f} s"
                  + (f" ({encoder.backend.kind})" if encoder else ""), file=sys.stderr, flush=True)
        for name in self.maps:
            try:
                for query in WARM_UP_QUERIES:
                    await self.find_goal(query, map=name)
            except IesmError as exc:
                print(f"iesm serve: warning: warm-up query on {name} failed: {exc}", file=sys.stderr)
            if navigation_available():
                self.planner(name)

    def planner(self, map: Optional[str] = None):
        """The `nav.PlanningGrid` of a map (inflated obstacle grid), built on first use and kept."""
        from ..nav import PlanningGrid

        store = self.store(map)
        name = store.scene.scene_id
        if name not in self._planners:
            self._planners[name] = PlanningGrid(store.scene)
        return self._planners[name]

    def _admission(self) -> asyncio.Semaphore:
        """At most `pool.size` queries of local models at once (per event loop): with more, all
        of them would share the cores and finish late together; this way the early ones finish
        early and the throughput is the same."""
        loop = asyncio.get_running_loop()
        if self._slots is None or self._slots[0] is not loop:
            self._slots = (loop, asyncio.Semaphore(self.pool.size))
        return self._slots[1]

    async def aclose(self) -> None:
        """Close the retrievers' model connections and stop the worker threads."""
        for retriever in self._retrievers.values():
            await retriever.aclose()
        self._retrievers.clear()
        self.pool.shutdown()

    # ------------------------------------------------------------------ tools
    async def find_goal(self, query: str, map: Optional[str] = None, method: str = "mtefr",
                        provider: Optional[str] = None) -> dict:
        """Find the map instance a sentence refers to (MTEFR), with where it is and the evidence in short.

        Returns the instance id, label, room and caption, its position [x, y, z] and box
        (centre, size; metres), the gate weights, each expert's top picks and the head of the
        fused ranking (goal first, then the alternatives, each with its score and box).

        Args:
            query: the sentence naming the goal object, e.g. "the red chair in the office"
            map: the served map's name (scene id; default: the first map)
            method: mtefr, spr, keyword or experts:<name>,<name>
            provider: model spec (default: the server's first enabled provider)
        """
        from ..retrieval.retriever import check_query

        check_query(query)
        retriever = self.retriever(map, method, provider)
        self._parses.arrived(query)
        if isinstance(retriever.model, OffLoopModel):
            async with self._admission():  # first come, first served on the worker pool
                await self._parses.settle(query)  # the queries arriving with it join its batch
                self._parses.parse(query)  # with the queries waiting behind it
                new_query()  # this query's model calls go to the pool as one job
                res = await retriever.aask(query)
        else:
            self._parses.parse(query)
            res = await retriever.aask(query)
        failed_calls = [c for c in res.calls if c.error]
        if res.calls and len(failed_calls) == len(res.calls):
            raise IesmError(f"all {len(res.calls)} model calls failed; the first: {failed_calls[0].error}",
                            provider or self.providers[0], "provider")
        name, store = res.names.get, retriever.store
        box = place(store, res.instance_id) if res.instance_id is not None else None
        ranking = [Ranked(id=i, name=name(i, "?"), score=round(res.scores[i], 3), box=place(store, i))
                   for i in res.ranking[:RANKING_SHOWN] if res.scores.get(i, 0.0) > 0]
        return FindGoalResult(
            map=store.scene.scene_id, query=res.query, method=res.method, found=res.instance_id is not None,
            instance_id=res.instance_id, label=res.label, room=res.room, caption=res.caption,
            position=box.center if box else None, box=box,
            gate={e: round(w, 3) for e, w in sorted(res.gate.items(), key=lambda kv: -kv[1])},
            experts={e: [{"id": i, "name": name(i, "?")} for i in ids] for e, ids in res.experts.items()},
            deciding_expert=res.deciding_expert, ranking=ranking, failures=res.failures,
            latency_ms=round(res.latency_ms, 2),
        ).model_dump(mode="json")

    async def list_maps(self) -> list[dict]:
        """The served maps: name, instance and room counts."""
        return [{"name": name, "instances": len(s.scene.instances), "rooms": len(s.scene.rooms),
                 "default": i == 0} for i, (name, s) in enumerate(self.maps.items())]

    async def plan_path(self, instance_id: int, start: tuple[float, float], map: Optional[str] = None) -> dict:
        """Plan a collision-free path from a start point to an instance (A* on the obstacle map).

        Returns status ("ok", "unreachable", "start_outside_map", "start_in_obstacle", ...),
        reachable, length_m and the waypoints [x, y] in metres from the start to a free cell
        next to the instance, and walls: where the walls planned around came from ("none: ..."
        when the map has no walls or room polygons and the path ignores walls).

        Args:
            instance_id: the goal instance id (e.g. find_goal's instance_id)
            start: [x, y] start point in world metres
            map: the served map's name (scene id; default: the first map)
        """
        path = self.planner(map).plan(int(instance_id), (float(start[0]), float(start[1])))
        if path.status == "unknown_instance":
            raise IesmError(path.message, self.store(map).scene.scene_id, "instance_id")
        return path.model_dump(mode="json")

    def map_summary(self, map: str) -> dict:
        """A map's content for the MCP resource: rooms, categories and every instance in brief."""
        store = self.store(map)
        scene = store.scene
        return {"scene_id": scene.scene_id, "rooms": store.list_rooms(), "categories": store.list_categories(),
                "grid": {"height": scene.grid.height, "width": scene.grid.width,
                         "cell_size": scene.grid.cell_size, "origin": list(scene.grid.origin)},
                "instances": store.find_instances(limit=len(scene.instances))}

    def _store_tool(self, name: str) -> Callable[..., Any]:
        """An async tool running `MapStore.<name>` on the map its `map` argument names; its
        signature and docstring are the method's plus `map`."""
        method = getattr(MapStore, name)
        hints = typing.get_type_hints(method)
        params = [p.replace(annotation=hints.get(p.name, Any))
                  for p in inspect.signature(method).parameters.values() if p.name != "self"]
        params.append(inspect.Parameter("map", inspect.Parameter.KEYWORD_ONLY, default=None,
                                        annotation=Optional[str]))

        async def tool(**arguments: Any) -> Any:
            store = self.store(arguments.pop("map", None))
            for arg, value in arguments.items():
                if isinstance(value, str) and len(value) > MAX_ARGUMENT_CHARS:
                    raise IesmError(f"{len(value)} characters; at most {MAX_ARGUMENT_CHARS} are accepted", None, arg)
            return getattr(store, name)(**arguments)

        tool.__name__ = tool.__qualname__ = name
        tool.__doc__ = (inspect.getdoc(method) or name) + _MAP_ARG_DOC
        tool.__signature__ = inspect.Signature(params, return_annotation=hints.get("return", Any))  # type: ignore[attr-defined]
        tool.__annotations__ = {**{p.name: p.annotation for p in params}, "return": hints.get("return", Any)}
        return tool

    async def call_tool(self, name: str, arguments: dict[str, Any]) -> Any:
        """Run tool `name` with JSON `arguments` (a function-calling loop's dispatcher): arguments
        are validated against the tool's signature; unknown tools, bad arguments and unknown
        maps or ids raise `IesmError`."""
        tool = next((t for t in self.tools() if t.__name__ == name), None)
        if tool is None:
            raise IesmError(f"unknown tool {name!r}; known: {', '.join(t.__name__ for t in self.tools())}",
                            None, "name")
        return await tool(**validate_arguments(tool, arguments))

    def tools(self) -> list[Callable[..., Any]]:
        """Every tool, as async functions whose signature and docstring are their schema:
        `find_goal`, `list_maps`, `plan_path` (when the navigation extra is installed), then the
        store tools in `mapstore.TOOLS` order. A new server-level tool is one method listed here.
        Built once per service (the same function objects every time, so their argument models
        stay memoised)."""
        if self._tools is None:
            server_tools = [self.find_goal, self.list_maps] + ([self.plan_path] if navigation_available() else [])
            self._tools = server_tools + [self._store_tool(n) for n in mapstore_module.TOOLS]
        return list(self._tools)


def bounded(tp: Any) -> Any:
    """`tp` with every `float` made a finite number within +-MAX_COORD (`Metres`) and every `int`
    an `Id` (not a boolean, 32 bits), inside tuples, lists and Optionals too."""
    if tp is float:
        return Metres
    if tp is int:
        return Id
    origin, args = typing.get_origin(tp), typing.get_args(tp)
    if origin is None or not args:
        return tp
    inner = tuple(a if a is Ellipsis else bounded(a) for a in args)
    if origin in (typing.Union, types.UnionType):
        return typing.Union[inner]
    if origin in (tuple, list, dict, set, frozenset):
        return origin[inner] if len(inner) > 1 else origin[inner[0]]
    return tp


@functools.lru_cache(maxsize=256)
def arguments_model(tool: Callable[..., Any]) -> type[BaseModel]:
    """A pydantic model of `tool`'s parameters (unknown arguments are refused; numbers must be
    finite and in range, see `bounded`). Memoised per tool: building the model costs about 1 ms
    of CPU, validating with it a few microseconds."""
    hints = typing.get_type_hints(tool)
    fields = {p.name: (bounded(hints.get(p.name, Any)), ... if p.default is p.empty else p.default)
              for p in inspect.signature(tool).parameters.values()}
    return create_model(f"{tool.__name__}_arguments", __config__=ConfigDict(extra="forbid", allow_inf_nan=False),
                        **fields)


def validate_arguments(tool: Callable[..., Any], arguments: dict[str, Any]) -> dict[str, Any]:
    """`arguments` validated against `tool`'s signature (`arguments_model`), or an `IesmError`
    in one sentence naming the argument."""
    try:
        valid = arguments_model(tool).model_validate(arguments)
    except ValidationError as exc:
        raise IesmError(argument_problem(tool.__name__, exc)) from None
    return {field: getattr(valid, field) for field in type(valid).model_fields}


def navigation_available() -> bool:
    """Whether `plan_path` can run: `iesm_agent.nav` and its OpenCV / pyastar2d dependencies."""
    return all(importlib.util.find_spec(m) is not None for m in ("iesm_agent.nav", "cv2", "pyastar2d"))


def tool_specs(service: MapService | None = None) -> list[dict]:
    """{"name", "description", "parameters"} per tool (the same schemas `MapStore.tool_specs()` gives
    its methods, plus `map`)."""
    return [function_schema(fn) for fn in (service or MapService()).tools()]


def format_specs(specs: list[dict], fmt: Literal["json", "openai", "mcp"] = "json") -> list[dict]:
    """Tool specs as plain JSON schemas (`json`), OpenAI function-calling `tools` entries
    (`openai`) or MCP `Tool` objects (`mcp`: name, description, inputSchema)."""
    if fmt == "json":
        return specs
    if fmt == "openai":
        return [{"type": "function", "function": spec} for spec in specs]
    if fmt == "mcp":
        return [{"name": s["name"], "description": s["description"], "inputSchema": s["parameters"]} for s in specs]
    raise IesmError(f"unknown tool spec format {fmt!r}; known: {', '.join(SPEC_FORMATS)}", None, "--format")
