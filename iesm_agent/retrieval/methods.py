"""Retrieval methods registered by name, behind one small protocol.

A method turns a `QueryContext` (the query read once, its candidate set and their views, the
call session) into an `Outcome`. Built in: `mtefr` (gate + every expert + fusion),
`mtefr-uniform` (the same experts, uniform weights: the gate switched off), `experts:<a>,<b>`
(MTEFR restricted to those experts, the paper's ablations), `spr` (single pass over all fields)
and `keyword` (HOV-SG style). `register_method(name, factory)` adds one.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from ..config import RetrievalConfig
from ..errors import IesmError
from ..understanding import QueryInfo
from .baselines import run_keyword, run_spr
from .calls import Outcome, Session
from .candidates import Candidates, CandidateViews
from .experts import ExpertSpec
from .mtefr import run_mtefr


@dataclass
class QueryContext:
    """Everything a method needs for one query; the query is analysed once, here."""

    query: str
    info: QueryInfo
    store: Any
    candidates: Candidates
    views: CandidateViews
    session: Session
    config: RetrievalConfig


class RetrievalMethod(Protocol):
    """`name` (as reported) and `run(ctx) -> Outcome`; model misbehaviour is recorded in the
    session, never raised."""

    name: str

    async def run(self, ctx: QueryContext) -> Outcome: ...


@dataclass
class Mtefr:
    name: str
    experts: list[ExpertSpec]
    gate: bool = True

    async def run(self, ctx: QueryContext) -> Outcome:
        if not ctx.candidates.ids:
            return Outcome()
        return await run_mtefr(ctx.session, ctx.query, self.experts, ctx.candidates.ids, ctx.views, ctx.config,
                               gate=self.gate)


@dataclass
class Spr:
    name: str = "spr"

    async def run(self, ctx: QueryContext) -> Outcome:
        if not ctx.candidates.ids:
            return Outcome()
        return await run_spr(ctx.session, ctx.query, ctx.candidates.ids, ctx.views, ctx.config)


@dataclass
class Keyword:
    name: str = "keyword"

    async def run(self, ctx: QueryContext) -> Outcome:
        return await run_keyword(ctx.session, ctx.store, ctx.query, ctx.config)


#: name -> factory(argument after "name:" or "", expert registry) -> method
MethodFactory = Callable[[str, Mapping[str, ExpertSpec]], RetrievalMethod]


def _all_experts(registry: Mapping[str, ExpertSpec]) -> list[ExpertSpec]:
    if not registry:
        raise IesmError("no expert specs found", "experts")
    return list(registry.values())


def _some_experts(arg: str, registry: Mapping[str, ExpertSpec]) -> RetrievalMethod:
    names = list(dict.fromkeys(n.strip() for n in arg.split(",") if n.strip()))
    unknown = [n for n in names if n not in registry]
    if not names or unknown:
        raise IesmError(f"unknown expert(s) {unknown or names}; known: {', '.join(registry)}", "method",
                        f"experts:{arg}")
    return Mtefr(f"experts:{','.join(names)}", [registry[n] for n in names])


_METHODS: dict[str, MethodFactory] = {
    "mtefr": lambda _arg, reg: Mtefr("mtefr", _all_experts(reg)),
    "mtefr-uniform": lambda _arg, reg: Mtefr("mtefr-uniform", _all_experts(reg), gate=False),
    "spr": lambda _arg, _reg: Spr(),
    "keyword": lambda _arg, _reg: Keyword(),
    "experts": _some_experts,
}


def register_method(name: str, factory: MethodFactory) -> None:
    """Add (or replace) a method; `name:ARG` specs pass ARG to the factory."""
    _METHODS[name] = factory


def method_names() -> list[str]:
    """Registered method names as users write them (`experts:<name>,<name>` for the ablations)."""
    return [f"{n}:<name>,<name>" if n == "experts" else n for n in _METHODS]


def resolve_method(spec: str, registry: Mapping[str, ExpertSpec]) -> RetrievalMethod:
    """The method a spec such as "mtefr" or "experts:obj,desc" names; unknown ones raise IesmError."""
    name, sep, arg = spec.strip().partition(":")
    factory = _METHODS.get(name)
    if factory is None or (name == "experts") != bool(sep):
        raise IesmError(f"unknown retrieval method {spec.strip()!r}; known: {', '.join(method_names())}", "method")
    return factory(arg, registry)


def is_method_name(token: str) -> bool:
    """True when `token` starts a method spec (used to split comma lists of methods)."""
    return token.partition(":")[0] in _METHODS and (token in _METHODS or ":" in token)
