"""The shared command line of the studies: seeds checked before any work, one-line errors, the
table printed, and the exact rebuilding command."""

from __future__ import annotations

from pathlib import Path

from iesm_agent.errors import IesmError
from iesm_agent.evals.studies import (AllowTuningSeeds, Out, Realism, Seeds, Work, run_checked, scene_rows,
                                      study_command, study_main, write_table)


def demo_study(ran: list):
    """A study command in the shape every study has; `ran` collects the seeds it was run on."""
    def command(seeds: Seeds = "10", realism: Realism = "realistic", out: Out = Path("unused"), work: Work = None,
                allow_tuning_seeds: AllowTuningSeeds = False) -> None:
        def run(seed_list):
            ran.append(seed_list)
            write_table(out, "Demo", study_command("demo", seeds, realism, out), f"seeds {seed_list}", {"seeds": seed_list})

        run_checked(seeds, realism, allow_tuning_seeds, out, run)

    return command


def test_tuning_seeds_are_refused_before_any_work(tmp_path, capsys):
    ran = []
    status = study_main("demo", "A demo study.", demo_study(ran), ["--seeds", "2-3", "--out", str(tmp_path / "out")])
    assert status == 2 and ran == []
    assert capsys.readouterr().err.strip().splitlines() == [
        "iesm: error: --seeds: seeds [2, 3] were used for tuning; report other seeds (or pass --allow-tuning-seeds)"]
    assert study_main("demo", "A demo study.", demo_study(ran),
                      ["--seeds", "2-3", "--allow-tuning-seeds", "--out", str(tmp_path / "out")]) == 0
    assert ran == [[2, 3]]
    # the table's rebuilding command carries the flag its tuning seeds need, and only then
    out = (tmp_path / "out").as_posix()
    assert (f"`python -m iesm_agent.evals.studies.demo --seeds 2-3 --realism realistic --allow-tuning-seeds "
            f"--out {out}`") in (tmp_path / "out" / "table.md").read_text()


def test_an_unknown_profile_or_option_is_refused_with_status_2(tmp_path, capsys):
    ran = []
    assert study_main("demo", "A demo study.", demo_study(ran), ["--realism", "glossy", "--out", str(tmp_path)]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [
        "iesm: error: --realism: no realism profile 'glossy'; choose from easy, realistic"]
    assert study_main("demo", "A demo study.", demo_study(ran), ["--sedes", "10"]) == 2
    assert "--sedes" in capsys.readouterr().err and ran == []


def test_the_table_is_written_with_its_command_and_printed(tmp_path, capsys):
    out = tmp_path / "out"
    assert study_main("demo", "A demo study.", demo_study([]), ["--seeds", "10,12", "--out", str(out)]) == 0
    table = (out / "table.md").read_text()
    assert f"`python -m iesm_agent.evals.studies.demo --seeds 10,12 --realism realistic --out {out.as_posix()}`" in table
    assert "seeds [10, 12]" in table and table in capsys.readouterr().out


def test_every_study_takes_its_documented_command_line(tmp_path, capsys):
    """Each study's own command line parses the documented options (and its extra ones) and
    refuses tuning seeds before rendering anything."""
    from iesm_agent.evals.studies import (calibration, captions, label_errors, mapping, mapping_causes, retrieval,
                                          retrieval_causes, room_causes, rooms, stacked, storage)

    for study in (calibration, captions, label_errors, mapping, mapping_causes, retrieval, retrieval_causes,
                  room_causes, rooms, stacked, storage):
        argv = ["--seeds", "2", "--realism", "realistic", "--out", str(tmp_path / study.__name__)]
        if study is mapping:
            argv += ["--size", "small"]
        assert study.main(argv) == 2, study.__name__
        assert "seeds [2] were used for tuning" in capsys.readouterr().err
        assert not (tmp_path / study.__name__).exists()
    assert mapping.main(["--size", "huge"]) == 2
    assert "huge" in capsys.readouterr().err


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
