"""MTEFR score-level fusion: worked examples computed by hand (paper Sec. 3.4.2)."""

import pytest

from iesm_agent.retrieval.fusion import fuse, lambda_schedule


def test_lambda_schedule_paper_values():
    assert lambda_schedule(2, 0.75, 16) == pytest.approx(0.75 + 0.25 * 1 / 17)
    assert lambda_schedule(3, 0.75, 16) == pytest.approx(0.75 + 0.25 * 2 / 18)
    assert lambda_schedule(1, 0.75, 16) == pytest.approx(0.75)


def test_peak_overrules_weighted_sum():
    # obj is confident about 1; room and desc both prefer 2 and put obj's pick nowhere.
    weights = {"obj": 0.6, "room": 0.2, "desc": 0.2}
    rankings = {"obj": [1, 2], "room": [2, 3], "desc": [2, 3]}
    res = fuse(weights, rankings)
    lam = 0.75 + 0.25 * 1 / 17
    s1, p1 = 0.6 * 2, 0.6 * 2
    s2, p2 = 0.6 * 1 + 0.2 * 2 + 0.2 * 2, 0.6 * 1
    s3, p3 = 0.2 * 1 + 0.2 * 1, 0.2 * 1
    assert res.lam == pytest.approx(lam)
    assert res.sum_scores[2] > res.sum_scores[1]  # consensus favours 2 ...
    assert res.sum_scores == pytest.approx({1: s1, 2: s2, 3: s3})
    assert res.peak_scores == pytest.approx({1: p1, 2: p2, 3: p3})
    assert res.scores[1] == pytest.approx(lam * p1 + (1 - lam) * s1)
    assert res.scores[2] == pytest.approx(lam * p2 + (1 - lam) * s2)
    assert res.best == 1  # ... but the peak decides
    assert res.ranking == (1, 2, 3)
    assert res.nu == {"obj": {1: 2, 2: 1}, "desc": {2: 2, 3: 1}, "room": {2: 2, 3: 1}}
    assert res.deciding_expert() == "obj"
    # with almost no peak reliance (gamma 0, huge mu) the weighted sum wins instead
    sum_led = fuse(weights, rankings, gamma=0.0, mu=1e9)
    assert sum_led.best == 2


def test_tie_broken_by_highest_weight_expert_then_names():
    # equal weights, mirrored rankings: U, S_sum and P all tie.
    res = fuse({"obj": 0.5, "room": 0.5}, {"obj": [1, 2], "room": [2, 1]})
    assert res.scores[1] == pytest.approx(res.scores[2])
    assert res.sum_scores[1] == pytest.approx(0.5 * 2 + 0.5 * 1)
    assert res.best == 1 and res.ranking == (1, 2)  # "obj" sorts first among equal weights
    swapped = fuse({"a": 0.5, "b": 0.5}, {"a": [2, 1], "b": [1, 2]})
    assert swapped.best == 2
    # the heavier expert decides a U/S/P tie regardless of names
    heavy = fuse({"a": 1.0, "b": 1.0, "z": 2.0}, {"a": [4, 9], "b": [9, 4], "z": [7]})
    assert heavy.scores[4] == pytest.approx(heavy.scores[9])
    assert heavy.best == 7


def test_tie_on_u_decided_by_sum_then_peak():
    u = 1 / 3  # three experts, equal weights
    # lambda = 1/2: id 5 (rank 1 for "a": P = S = 2u) ties on U with id 6 (rank 2 for all three:
    # P = u, S = 3u); 6 has the larger weighted sum, so consensus wins the tie.
    res = fuse({"a": 1, "b": 1, "c": 1}, {"a": [5, 6], "b": [7, 6], "c": [8, 6]},
               gamma=0.5, mu=float("inf"))
    assert res.lam == pytest.approx(0.5)
    assert res.scores[5] == pytest.approx(0.5 * 2 * u + 0.5 * 2 * u)
    assert res.scores[6] == pytest.approx(0.5 * u + 0.5 * 3 * u)
    assert res.ranking == (6, 5, 7, 8)  # 5, 7, 8 tie on U, S, P: order of experts a, b, c
    # lambda = 0: U = S. ids 10, 11, 1 (one first place each: S = P = 2u) tie on S with id 2
    # (second for "a" and "b": S = 2u, P = u); the lower peak puts 2 last although the
    # heaviest-first rank vector alone would have preferred it to 1.
    res = fuse({"a": 1, "b": 1, "c": 1}, {"a": [10, 2], "b": [11, 2], "c": [1]},
               gamma=0.0, mu=float("inf"))
    assert res.lam == 0.0
    assert res.scores[2] == pytest.approx(res.scores[1]) == pytest.approx(2 * u)
    assert res.ranking == (10, 11, 1, 2)


def test_abstaining_expert_weight_is_redistributed_over_the_experts_that_answered():
    lam = 0.75 + 0.25 * 1 / 17                       # kappa 2, gamma 0.75, mu 16
    for rankings in ({"obj": [7, 3], "room": []}, {"obj": [7, 3]}):
        res = fuse({"obj": 0.5, "room": 0.5}, rankings)
        assert res.weights == {"obj": 1.0} and res.abstained == {"room": 0.5}
        assert res.scores[7] == pytest.approx(lam * 1.0 * 2 + (1 - lam) * 1.0 * 2)   # nu = 2 at rank 1
        assert res.scores[3] == pytest.approx(1.0)                                   # nu = 1 at rank 2
        assert res.ranking == (7, 3) and not res.uniform_fallback
    # three experts, spatial abstains: 0.5 and 0.3 become 0.5/0.8 and 0.3/0.8
    res = fuse({"obj": 0.5, "room": 0.3, "spatial": 0.2}, {"obj": [7, 3], "room": [3, 7], "spatial": []})
    assert res.weights == pytest.approx({"obj": 0.625, "room": 0.375}) and res.abstained == {"spatial": 0.2}
    s7, s3 = 0.625 * 2 + 0.375 * 1, 0.625 * 1 + 0.375 * 2                # S_sum
    p7, p3 = 0.625 * 2, 0.375 * 2                                        # P = max_e w_e nu_e
    assert res.scores[7] == pytest.approx(lam * p7 + (1 - lam) * s7)
    assert res.scores[3] == pytest.approx(lam * p3 + (1 - lam) * s3)
    assert res.best == 7
    empty = fuse({"obj": 1.0}, {"obj": []})
    assert empty.best is None and empty.ranking == () and empty.scores == {}


def test_weights_are_normalised():
    raw = fuse({"obj": 3, "room": 1}, {"obj": [1], "room": [2]})
    unit = fuse({"obj": 0.75, "room": 0.25}, {"obj": [1], "room": [2]})
    assert raw.weights == pytest.approx({"obj": 0.75, "room": 0.25})
    assert raw.scores == pytest.approx(unit.scores)
    assert raw.scores[1] == pytest.approx(0.75 * 2)  # kappa 2, rank 1, S = P


def test_zero_or_missing_weights_fall_back_to_uniform_over_ranked_experts():
    lam = 0.75 + 0.25 * 1 / 17
    for weights in ({"obj": 0, "room": 0}, {}, {"abs": 1.0}):
        res = fuse(weights, {"obj": [1, 2], "room": [2]})
        assert res.uniform_fallback
        assert res.weights == pytest.approx({"obj": 0.5, "room": 0.5})
        assert res.scores[2] == pytest.approx(lam * 1.0 + (1 - lam) * (0.5 * 1 + 0.5 * 2))
        assert res.best == 2


def test_negative_weight_is_an_error():
    with pytest.raises(ValueError, match="obj"):
        fuse({"obj": -0.1, "room": 1.1}, {"obj": [1]})


def test_kappa_three_ignores_positions_beyond_kappa_and_duplicates():
    lam = 0.75 + 0.25 * 2 / 18
    res = fuse({"obj": 0.5, "desc": 0.5}, {"obj": [1, 1, 2, 3, 4], "desc": [3, 9, 2, 1]}, kappa=3)
    assert res.lam == pytest.approx(lam)
    assert 4 not in res.scores  # 5th position of obj, 4th of nothing
    assert res.sum_scores[1] == pytest.approx(0.5 * 3)  # desc's 4th place is beyond kappa
    assert res.sum_scores[2] == pytest.approx(0.5 * 2 + 0.5 * 1)
    assert res.sum_scores[3] == pytest.approx(0.5 * 1 + 0.5 * 3)
    assert res.peak_scores[3] == pytest.approx(0.5 * 3)
    assert res.scores[3] == pytest.approx(lam * 1.5 + (1 - lam) * 2.0)
    assert res.best == 3
    assert res.ranking == (3, 1, 2, 9)


def test_deciding_expert_separates_winner_from_runner_up():
    # both experts put 34 first (equal peaks); obj's second pick 7 is the runner-up, so the room
    # expert, which gives 7 nothing, is what separates 34 from it: margin 0.5 * 2 vs 0.5 * (2 - 1).
    res = fuse({"obj": 0.5, "room": 0.5}, {"obj": [34, 7], "room": [34, 12]})
    assert res.ranking[:2] == (34, 7)
    assert res.deciding_expert() == "room"
    alone = fuse({"obj": 1.0, "room": 1.0}, {"obj": [5]})
    assert alone.deciding_expert() == "obj"
    assert fuse({"obj": 1.0}, {}).deciding_expert() is None
