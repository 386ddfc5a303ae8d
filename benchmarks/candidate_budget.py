"""Candidate recall of the cheap pre-ranking (`retrieval.candidates.select_candidates`) at
budgets G over the shipped suites: the share of queries with an accepted instance among the G
candidates, overall and per map. The measurement behind `providers.base.LLM_CANDIDATES`; run
`python benchmarks/candidate_budget.py` from the repository root (no model is called)."""

from collections import defaultdict
from pathlib import Path

from iesm_agent.evals.suite import MapRegistry, load_suites
from iesm_agent.retrieval.candidates import select_candidates
from iesm_agent.store.mapstore import MapStore
from iesm_agent.understanding import analyse_query

BUDGETS = (5, 10, 15, 20, 30, 100)


def main() -> None:
    registry = MapRegistry()
    suite = load_suites(sorted(str(p) for p in Path("evals").glob("*.jsonl")), registry=registry)
    stores: dict = {}
    hits: dict = defaultdict(lambda: defaultdict(int))
    counts: dict = defaultdict(int)
    for entry in suite.entries:
        store = stores.get(entry.map_path) or stores.setdefault(entry.map_path, MapStore(registry.get(entry.map_path)))
        query, name = entry.query, Path(entry.map_path).name
        info = analyse_query(query.query)
        counts[name] += 1
        for budget in BUDGETS:
            ids = select_candidates(store, query.query, info, budget).ids
            hits[name][budget] += any(a in ids for a in query.accept)
    total = sum(counts.values())
    print(f"{total} queries; instances per map: "
          + ", ".join(f"{Path(p).name} {len(s.scene.instances)}" for p, s in stores.items()))
    for budget in BUDGETS:
        overall = sum(h[budget] for h in hits.values()) / total
        print(f"G={budget:>3}: recall {overall:.3f}  "
              + "  ".join(f"{name} {hits[name][budget] / counts[name]:.3f}" for name in counts))


if __name__ == "__main__":
    main()
