"""Shared fixtures: the shipped apartment map, and the paper's published maps when present."""

from __future__ import annotations

from pathlib import Path

import pytest

from iesm_agent.resources import shipped_map
from iesm_agent.store import MapStore

REPO = Path(__file__).resolve().parents[1]
IESM_MAPS = REPO.parent / "shared" / "data" / "iesm_maps"


@pytest.fixture(scope="session")
def apartment_path() -> Path:
    """map_store/apartment.iesm (read-only)."""
    return shipped_map("apartment")


@pytest.fixture(scope="session")
def apartment_store(apartment_path) -> MapStore:
    """A MapStore over the shipped apartment; shared by tests, do not mutate."""
    return MapStore.load(apartment_path)


@pytest.fixture(scope="session")
def iesm_maps_dir() -> Path:
    """The paper's published maps (../shared/data/iesm_maps beside the repo); skipped when absent."""
    if not (IESM_MAPS / "scene_00829_caption.json").is_file():
        pytest.skip("../shared/data/iesm_maps not available")
    return IESM_MAPS


@pytest.fixture(scope="session")
def lib():
    """The shipped prompt templates."""
    from iesm_agent.prompting import PromptLibrary

    return PromptLibrary()


@pytest.fixture(scope="session")
def model():
    """The offline model on lexicons alone (deterministic, no embedding model to load)."""
    from iesm_agent.providers.offline import OfflineModel

    return OfflineModel(use_embeddings=False)


def pytest_terminal_summary(terminalreporter):
    """The fuzz tests' tries per reader and outcome (tests/fuzzing.py), when any ran."""
    import sys

    fuzzing = sys.modules.get("fuzzing")
    if fuzzing is None or not fuzzing.Tally.counts:
        return
    terminalreporter.section("fuzz cases per reader")
    for reader, outcomes in sorted(fuzzing.Tally.counts.items()):
        refused = sum(n for k, n in outcomes.items() if k.endswith("refused"))
        total = sum(outcomes.values())
        terminalreporter.write_line(f"{reader}: {total} cases, {refused} refused cleanly, {total - refused} accepted "
                                    f"as valid; " + ", ".join(f"{k} {n}" for k, n in sorted(outcomes.items())))
