"""Score-level fusion of expert rankings (MTEFR, paper Sec. 3.4.2).

For expert e with weight w_e and a ranking of candidate ids (best first), a candidate d at
1-based rank rho inside the top-kappa gets nu_{e,d} = kappa - rho + 1, else 0. Then

    S_sum_d = sum_e w_e nu_{e,d}        P_d = max_e w_e nu_{e,d}
    lambda  = gamma + (1 - gamma) (kappa - 1) / ((kappa - 1) + mu)
    U_d     = lambda P_d + (1 - lambda) S_sum_d          d* = argmax_d U_d

Tie rule (deterministic): higher U, then higher S_sum (consensus), then higher P, then the
better ranks given by the experts taken in order of decreasing weight (name order among equal
weights; unranked counts as kappa + 1). That rank vector differs for any two scored ids, so the
order is total. Scores are compared rounded to 12 decimals so that float noise never decides.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field


@dataclass(frozen=True)
class FusionResult:
    """`ranking` holds every id with U > 0, best first; `weights` are the normalised weights used;
    `nu` the rank scores nu_{e,d} per expert (experts with a ranking, heaviest first)."""

    best: int | None
    ranking: tuple[int, ...]
    scores: dict[int, float]
    sum_scores: dict[int, float]
    peak_scores: dict[int, float]
    lam: float
    weights: dict[str, float] = field(default_factory=dict)
    nu: dict[str, dict[int, int]] = field(default_factory=dict)
    uniform_fallback: bool = False
    #: gate weights (normalised over every expert) of the experts that returned no ranking; their
    #: weight is redistributed over the experts that answered
    abstained: dict[str, float] = field(default_factory=dict)

    def deciding_expert(self) -> str | None:
        """The expert whose weighted rank score w_e (nu_{e,best} - nu_{e,runner-up}) most separates
        `best` from the runner-up (its peak contribution when nothing else scored); the heavier
        expert, then the first by name, on a tie. None when nothing scored."""
        if self.best is None:
            return None
        second = self.ranking[1] if len(self.ranking) > 1 else None

        def margin(name: str) -> float:
            nu = self.nu[name]
            return self.weights.get(name, 0.0) * (nu.get(self.best, 0) - nu.get(second, 0))

        return max(self.nu, key=margin)  # first maximal in heaviest-first order


def lambda_schedule(kappa: int, gamma: float, mu: float) -> float:
    """lambda = gamma + (1 - gamma) (kappa - 1) / ((kappa - 1) + mu); gamma when kappa = 1."""
    denom = (kappa - 1) + mu
    return gamma + (1 - gamma) * ((kappa - 1) / denom if denom > 0 else 0.0)


def normalise_weights(weights: Mapping[str, float], ranked: Sequence[str]) -> tuple[dict[str, float], bool]:
    """Weights of the `ranked` experts (those that answered) scaled to sum 1, so an abstaining
    expert's weight is redistributed over them in proportion to theirs; uniform over `ranked`
    when none of them has weight. Returns (weights, uniform_fallback). Negative or non-finite
    weights raise ValueError."""
    for name, w in weights.items():
        if not math.isfinite(w) or w < 0:
            raise ValueError(f"expert weight must be finite and >= 0, got {name}={w!r}")
    if not any(weights.get(name, 0.0) > 0 for name in ranked):
        return ({name: 1.0 / len(ranked) for name in ranked} if ranked else {}), bool(ranked)
    total = sum(weights.get(name, 0.0) for name in ranked)
    return {name: weights.get(name, 0.0) / total for name in ranked}, False


def fuse(weights: Mapping[str, float], rankings: Mapping[str, Sequence[int]], *,
         kappa: int = 2, gamma: float = 0.75, mu: float = 16) -> FusionResult:
    """Fuse expert `rankings` (name -> ids best first) under gate `weights` (name -> weight)."""
    if kappa < 1:
        raise ValueError(f"kappa must be >= 1, got {kappa}")
    ranked = sorted(name for name, ids in rankings.items() if ids)
    w, fallback = normalise_weights(weights, ranked)
    total = sum(weights.values())
    abstained = {name: (weights[name] / total if total > 0 else 0.0) for name in sorted(weights) if name not in ranked}
    lam = lambda_schedule(kappa, gamma, mu)

    nu: dict[str, dict[int, int]] = {}  # expert -> id -> kappa - rank + 1, top-kappa only
    for name in sorted(ranked, key=lambda name: (-w.get(name, 0.0), name)):
        scored: dict[int, int] = {}
        for d in rankings[name]:
            if d not in scored:
                scored[d] = kappa - len(scored)
                if len(scored) == kappa:
                    break
        nu[name] = scored

    sum_scores: dict[int, float] = {}
    peak_scores: dict[int, float] = {}
    for name in nu:
        we = w.get(name, 0.0)
        if we <= 0:
            continue
        for d, nu_ed in nu[name].items():
            s = we * nu_ed
            sum_scores[d] = sum_scores.get(d, 0.0) + s
            peak_scores[d] = max(peak_scores.get(d, 0.0), s)
    scores = {d: lam * peak_scores[d] + (1 - lam) * sum_scores[d] for d in sum_scores}

    def key(d: int):
        return (-round(scores[d], 12), -round(sum_scores[d], 12), -round(peak_scores[d], 12),
                tuple(-nu[name].get(d, 0) for name in nu))

    ranking = tuple(sorted(scores, key=key))
    return FusionResult(best=ranking[0] if ranking else None, ranking=ranking, scores=scores,
                        sum_scores=sum_scores, peak_scores=peak_scores, lam=lam,
                        weights=w, nu=nu, uniform_fallback=fallback, abstained=abstained)
