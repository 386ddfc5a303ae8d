"""The wheel ships prompts/, experts/ and map_store/ as package data, and they resolve from it."""

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]


@pytest.mark.slow
def test_wheel_ships_resource_folders(tmp_path):
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w", str(tmp_path), str(REPO)],
        check=True, capture_output=True,
    )
    (wheel,) = tmp_path.glob("iesm_agent-*.whl")
    names = set(zipfile.ZipFile(wheel).namelist())
    for folder in ("prompts", "experts", "map_store"):
        shipped = {p.relative_to(REPO).as_posix() for p in (REPO / folder).rglob("*") if p.is_file()}
        assert shipped, f"{folder}/ is empty"
        for rel in shipped:
            assert f"iesm_agent/_data/{rel}" in names, f"{rel} missing from the wheel"
    # test doubles (the loopback and hostile model servers) live with the tests, not the package
    assert not [n for n in names if "loopback" in n or "hostile" in n]


def test_resource_dirs_resolve_from_checkout():
    from iesm_agent.resources import resource_dir

    for folder in ("prompts", "experts", "map_store"):
        assert resource_dir(folder).is_dir()
    with pytest.raises(FileNotFoundError):
        resource_dir("no_such_folder")
