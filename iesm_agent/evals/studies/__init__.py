"""Studies: one command per results table, each writing OUT/table.md and OUT/summary.json.

    python -m iesm_agent.evals.studies.mapping --seeds 0-4 --out evals/mapping
    python -m iesm_agent.evals.studies.rooms --seeds 0-4 --out evals/rooms
"""

from __future__ import annotations

from ...errors import IesmError


def parse_seeds(text: str) -> list[int]:
    """"0-4" or "0,2,5" -> seeds."""
    try:
        seeds: list[int] = []
        for part in text.split(","):
            lo, _, hi = part.partition("-")
            seeds += list(range(int(lo), int(hi or lo) + 1))
    except ValueError:
        raise IesmError(f"expected seeds like 0-4 or 0,2,5, got {text!r}", None, "--seeds") from None
    return seeds
