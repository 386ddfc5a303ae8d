"""What `find_goal` returns, as a pydantic model (the MCP output schema), and tool argument
errors as one sentence naming the argument."""

from __future__ import annotations

from typing import Optional

from pydantic import BaseModel, Field, ValidationError


class Place(BaseModel):
    """An instance's axis-aligned box in world metres."""

    center: list[float] = Field(description="[x, y, z] box centre (m, rounded to cm)")
    size: list[float] = Field(description="[dx, dy, dz] box extent (m, rounded to cm)")


class Pick(BaseModel):
    """An instance an expert put in its top kappa."""

    id: int
    name: str = Field(description="label (room)")


class Ranked(Pick):
    """An entry of the fused ranking, with its fused score and box."""

    score: float = Field(description="fused score U, > 0")
    box: Place


class FindGoalResult(BaseModel):
    """The goal a sentence refers to, where it is, and the evidence in short."""

    map: str
    query: str
    method: str
    found: bool
    instance_id: Optional[int] = None
    label: Optional[str] = None
    room: Optional[str] = None
    caption: Optional[str] = None
    position: Optional[list[float]] = Field(None, description="[x, y, z] of the goal's box centre (m)")
    box: Optional[Place] = Field(None, description="the goal's box")
    gate: dict[str, float] = Field(description="expert -> gate weight")
    experts: dict[str, list[Pick]] = Field(description="expert -> its top picks")
    deciding_expert: Optional[str] = None
    ranking: list[Ranked] = Field(description="head of the fused ranking, goal first, then the alternatives "
                                              "(only instances with a positive score)")
    failures: list[str]
    latency_ms: float = Field(description="retrieval wall time (ms), model loading excluded")


def place(store, instance_id: int) -> Place:
    """The box of `instance_id` in `store` (a MapStore)."""
    view = store.candidate_view(instance_id, ["center", "size"])
    return Place(center=view["center"], size=view["size"])


def argument_problem(tool: str, exc: ValidationError) -> str:
    """One sentence naming each bad argument of `tool`, e.g. "bad argument for plan_path: start
    (input should be a valid tuple)"; no pydantic links or input echoes."""
    parts = []
    for err in exc.errors(include_url=False, include_input=False):
        loc = err.get("loc") or ()
        name = str(loc[0]) if loc else "arguments"
        name += "".join(f"[{p}]" for p in loc[1:])
        kind = err.get("type")
        if kind == "missing":
            parts.append(f"{name} is missing")
        elif kind == "extra_forbidden":
            parts.append(f"{name} is not an argument of {tool}")
        else:
            msg = str(err.get("msg", "is invalid"))
            parts.append(f"{name} ({msg[:1].lower() + msg[1:]})")
    plural = "s" if len(parts) > 1 else ""
    return f"bad argument{plural} for {tool}: {'; '.join(parts)}"
