"""The shared command line of the studies: seeds checked before any work, one-line errors, the
table printed, and the exact rebuilding command."""

from __future__ import annotations

from iesm_agent.errors import IesmError
from iesm_agent.evals.studies import scene_rows, study_command, study_main, write_table


def test_tuning_seeds_are_refused_before_any_work(tmp_path, capsys):
    ran = []
    status = study_main("demo", "A demo study.", "10", str(tmp_path / "out"), lambda a, s: ran.append(s), ["--seeds", "2-3"])
    assert status == 2 and ran == []
    assert capsys.readouterr().err.strip().splitlines() == [
        "iesm: error: --seeds: seeds [2, 3] were used for tuning; report other seeds (or pass --allow-tuning-seeds)"]


def test_the_table_is_written_with_its_command_and_printed(tmp_path, capsys):
    out = tmp_path / "out"

    def run(args, seeds):
        write_table(args.out, "Demo", study_command("demo", args.seeds, args.realism, args.out), f"seeds {seeds}",
                    {"seeds": seeds})

    assert study_main("demo", "A demo study.", "10", str(out), run, ["--seeds", "10,12"]) == 0
    table = (out / "table.md").read_text()
    assert f"`python -m iesm_agent.evals.studies.demo --seeds 10,12 --realism realistic --out {out.as_posix()}`" in table
    assert "seeds [10, 12]" in table and table in capsys.readouterr().out


def test_a_scene_that_cannot_be_made_is_skipped_and_listed():
    def score(seed):
        if seed == 11:
            raise IesmError("no room for a door")
        return {"x": seed}

    rows, skipped = scene_rows([10, 11, 12], score, lambda r: f"x {r['x']}", "walled")
    assert rows == [{"seed": 10, "x": 10}, {"seed": 12, "x": 12}]
    assert skipped == ["walled seed 11: no room for a door"]


def test_kept_scenes_live_under_the_fingerprint_of_the_code_that_made_them(tmp_path, monkeypatch):
    import iesm_agent.evals.studies as studies

    with studies.scene_frames(tmp_path) as cache:
        first = cache.root
    assert first.parent == tmp_path and first.name == f"code-{studies.source_fingerprint()}"
    monkeypatch.setattr(studies, "source_fingerprint", lambda: "changedcode0")  # as after an edit
    with studies.scene_frames(tmp_path) as cache:
        assert cache.root == tmp_path / "code-changedcode0" != first
