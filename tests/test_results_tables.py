"""The committed tables under docs/results/ still match what their commands produce, checked on
the first seed of each realistic table (one walled scene, rendered once; about a minute)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from iesm_agent.config import MappingConfig
from iesm_agent.evals.studies import SceneCache

pytestmark = pytest.mark.slow

RESULTS = Path(__file__).resolve().parents[1] / "docs" / "results"


def _summary(name: str) -> dict:
    path = RESULTS / name / "summary.json"
    if not path.is_file():
        pytest.skip(f"{path} not committed")
    return json.loads(path.read_text())


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    mapping = _summary("mapping-realistic")
    seed = mapping["seeds"][0]
    cache = SceneCache(tmp_path_factory.mktemp("tables"))
    frames = cache.prepare(seed, "small", False, "realistic")
    space = json.loads((frames / "scene.json").read_text())["embedding_space"]
    first = next(iter(mapping["scenes"].values()))
    if first["scene"]["embedding_space"] != space:
        pytest.skip(f"tables were made in {first['scene']['embedding_space']}, this environment has {space}")
    return seed, cache, frames


def test_mapping_table_first_seed(scene):
    from iesm_agent.evals.studies.mapping import study_scene

    seed, _cache, frames = scene
    committed = next(iter(_summary("mapping-realistic")["scenes"].values()))
    now = study_scene(frames, MappingConfig())
    for footprint in ("observed", "full"):
        for method in ("ours", "ours_no_second_pass", "pointwise_2d", "pointwise_2d_same"):
            a, b = committed[footprint][method], now[footprint][method]
            assert a["n_pred"] == b["n_pred"] and a["n_matched"] == b["n_matched"], (footprint, method)
            assert a["auc_top"] == pytest.approx(b["auc_top"], abs=1e-9), (footprint, method)
            assert a["topdown"] == pytest.approx(b["topdown"], abs=1e-9), (footprint, method)


def test_calibration_and_caption_tables_first_seed(scene):
    from iesm_agent.evals.studies import calibration, captions

    seed, cache, frames = scene
    cal = _summary("calibration-realistic")["rows"][str(seed)]
    assert calibration.frame_top1(frames)["top1"] == pytest.approx(cal["top1"], abs=1e-9)
    cap = _summary("captions-realistic")["rows"][str(seed)]
    now = captions.score_scene(frames, cache.built(frames))
    assert (now["n"], now["colour_acc"]) == (cap["n"], pytest.approx(cap["colour_acc"], abs=1e-9))


def test_rooms_table_first_seed_walled(scene):
    from iesm_agent.evals.studies.rooms import score_scene

    seed, cache, frames = scene
    committed = _summary("rooms-realistic")["scenes"]["walled"][0]
    assert committed["seed"] == seed
    now = score_scene(frames, cache.built(frames), seed)
    for method in ("baseline", "lsd", "split"):
        assert now[method]["miou"] == pytest.approx(committed[method]["miou"], abs=1e-9), method


def test_retrieval_table_first_seed(scene, tmp_path):
    from iesm_agent.evals.studies.retrieval import METHODS, score_scene

    seed, _cache, frames = scene
    committed = _summary("retrieval-realistic")["scenes"][0]
    assert committed["seed"] == seed
    now = score_scene(frames, seed, tmp_path)
    assert (now["queries"], now["dropped"]) == (committed["queries"], committed["dropped"])
    for method in METHODS:
        assert now[method]["osr_all"] == pytest.approx(committed[method]["osr_all"], abs=1e-9), method
        assert now[method]["nsr"] == pytest.approx(committed[method]["nsr"], abs=1e-9), method


def test_storage_table_first_seed(scene, tmp_path):
    from iesm_agent.evals.studies.storage import measure_scene

    seed, _cache, frames = scene
    committed = _summary("storage-realistic")["scenes"][0]
    assert committed["seed"] == seed
    now = measure_scene(frames, seed, tmp_path / "map.iesm")
    for key in ("instances", "observed_cells", "voxels", "vlmaps", "hovsg"):
        assert now[key] == committed[key], key
    assert now["ours"] == pytest.approx(committed["ours"], rel=0.01)
