"""Bad recordings through `iesm segment` (issue 31: 5, 6, 7, 9; 2 for paths): every case exits 2
with one `iesm: error:` line (or 0 when the input is valid, or a frame is skipped and counted),
never a traceback, nothing written, nothing deleted. The named cases are the reproductions of the
issue; the seeded mutations run 20 cases per layout here and `FUZZ_CASES` / 8 per layout (50 by
default) under `-m slow`.
Peak memory of the same cases in a fresh process: benchmarks/bench_bad_recordings.py."""

from __future__ import annotations

import json
import os
import random
import shutil
from pathlib import Path

import numpy as np
import pytest

from fuzzing import FAST, SLOW, Tally, check_cli
from recordings import WRITERS, jpeg_claiming, png_claiming

from iesm_agent.cli import run

pytest.importorskip("cv2")
SEGMENT = ["--segmenter", "geometric"]


def segment(src: Path, out: Path, *extra: str) -> list[str]:
    return ["segment", str(src), "-o", str(out), *SEGMENT, *extra]


def refused(argv: list[str], capsys, needle: str, outputs: tuple[Path, ...] = ()) -> str:
    """`argv` exits 2 with one error line holding `needle`, nothing of `outputs` written."""
    assert check_cli(argv, capsys, outputs=outputs, may_pass=False) == 2
    return needle


def one_line_error(argv: list[str], capsys, needle: str) -> None:
    code = run(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and err[0].startswith("iesm: error:") and "Traceback" not in err[0], err
    assert needle in err[0], err


@pytest.fixture()
def seven(tmp_path):
    return WRITERS["7scenes"](tmp_path / "seven")


@pytest.mark.parametrize("layout", ["7scenes", "replica", "scannet", "tum"])
def test_the_tiny_recordings_segment(layout, tmp_path, capsys):
    src = WRITERS[layout](tmp_path / layout)
    out = tmp_path / "out"
    assert run(segment(src, out)) == 0, capsys.readouterr().err
    scene = json.loads((out / "scene.json").read_text())
    assert scene["source"]["layout"] == layout and scene["n_frames"] >= 2


# ---------------------------------------------------------------------------------- readers (6)
def _seven_case(name: str, d: Path) -> None:
    """Damage the 7-Scenes recording `d` as the issue's case `name` did."""
    if name == "frame-abc":
        for p in d.glob("frame-*"):
            p.unlink()
        (d / "frame-abc.color.jpg").write_bytes(b"x")
    elif name == "bmp":
        for p in d.glob("frame-*.color.png"):
            p.rename(p.with_suffix(".bmp"))
    elif name == "pose-far":
        (d / "frame-000001.pose.txt").write_text("1 0 0 1e8\n0 1 0 0\n0 0 1 0\n0 0 0 1\n")
    elif name == "pose-1e5":
        (d / "frame-000001.pose.txt").write_text("1 0 0 1e5\n0 1 0 0\n0 0 1 0\n0 0 0 1\n")
    elif name == "pose-dev-zero":
        (d / "frame-000001.pose.txt").unlink()
        (d / "frame-000001.pose.txt").symlink_to("/dev/zero")
    elif name == "pose-fifo":
        (d / "frame-000001.pose.txt").unlink()
        os.mkfifo(d / "frame-000001.pose.txt")
    elif name == "depth-bomb":
        (d / "frame-000001.depth.png").write_bytes(png_claiming(20000, 20000))
    elif name == "every-depth-bomb":
        for p in d.glob("frame-*.depth.png"):
            p.write_bytes(png_claiming(20000, 20000))
    elif name == "colour-bomb":
        (d / "frame-000001.color.png").unlink()
        (d / "frame-000001.color.jpg").write_bytes(jpeg_claiming(30000, 30000))
    elif name == "all-zero-depth":
        import cv2

        for p in d.glob("frame-*.depth.png"):
            p.write_bytes(cv2.imencode(".png", np.zeros((48, 64), np.uint16))[1].tobytes())
    elif name == "fx-1e300":
        (d / "camera-intrinsics.txt").write_text("1e300 0 31.5\n0 50 23.5\n0 0 1\n")
    elif name == "cx-1e30":
        (d / "camera-intrinsics.txt").write_text("50 0 1e30\n0 50 23.5\n0 0 1\n")
    elif name == "intrinsics-inf":
        (d / "camera-intrinsics.txt").write_text("inf 0 31.5\n0 50 23.5\n0 0 1\n")
    elif name == "pose-not-utf8":
        (d / "frame-000001.pose.txt").write_bytes(b"\xff\xfe 1 0 0\n")
    elif name == "depth-text":
        (d / "frame-000001.depth.png").write_text("not an image")
    else:
        raise AssertionError(name)


SEVEN_CASES = {"frame-abc": "no 7-Scenes frames", "bmp": "no 7-Scenes frames", "pose-far": "too far",
               "pose-1e5": "too far", "pose-dev-zero": "not a regular file", "pose-fifo": "not a regular file",
               "depth-bomb": "20000 x 20000", "every-depth-bomb": "20000 x 20000 pixels",
               "colour-bomb": "30000 x 30000", "all-zero-depth": "no reading", "fx-1e300": "fx = 1e+300",
               "cx-1e30": "cx = 1e+30", "intrinsics-inf": "fx", "pose-not-utf8": "not UTF-8",
               "depth-text": "not a readable image"}


@pytest.mark.parametrize("name", list(SEVEN_CASES))
def test_bad_seven_scenes_recording_is_one_line(name, seven, tmp_path, capsys):
    _seven_case(name, seven)
    out = tmp_path / "out"
    refused(segment(seven, out), capsys, SEVEN_CASES[name], outputs=(out,))
    one_line_error(segment(seven, out), capsys, SEVEN_CASES[name])
    assert not out.exists() and not list(tmp_path.glob(".out.iesm-tmp.*"))


@pytest.mark.parametrize("name", ["pose-far", "pose-dev-zero", "pose-fifo", "depth-bomb", "colour-bomb",
                                  "pose-not-utf8", "depth-text"])
def test_skip_bad_frames_skips_and_counts_the_bad_frame(name, seven, tmp_path, capsys):
    _seven_case(name, seven)
    out = tmp_path / "out"
    assert run(segment(seven, out, "--skip-bad-frames")) == 0, capsys.readouterr().err
    said = capsys.readouterr().out
    assert "1 frames skipped" in said, said
    assert json.loads((out / "scene.json").read_text())["n_frames"] == 2


def test_skip_bad_frames_with_a_wrong_size_first_frame_keeps_the_good_ones(seven, tmp_path, capsys):
    import cv2

    (seven / "frame-000000.depth.png").write_bytes(cv2.imencode(".png", np.full((24, 32), 2000, np.uint16))[1].tobytes())
    out = tmp_path / "out"
    assert run(segment(seven, out, "--skip-bad-frames")) == 0, capsys.readouterr().err
    said = capsys.readouterr().out
    scene = json.loads((out / "scene.json").read_text())
    assert scene["n_frames"] == 2 and "frame-000000" in scene["source"]["skipped"], said
    assert json.loads((out / "intrinsics.json").read_text())["width"] == 64


def _replica_case(name: str, d: Path) -> None:
    if name == "params-infinity":
        (d / "cam_params.json").write_text('{"camera": {"w": 64, "h": 48, "fx": Infinity, "fy": 50, "cx": 31.5, '
                                           '"cy": 23.5, "scale": 6553.5}}')
    elif name == "params-deep":
        (d / "cam_params.json").write_text('{"camera": ' + "[" * 100_000 + "]" * 100_000 + "}")
    elif name == "params-1e400":
        (d / "cam_params.json").write_text('{"camera": {"w": 1e400, "h": 48, "fx": 50, "fy": 50, "cx": 31.5, '
                                           '"cy": 23.5, "scale": 6553.5}}')
    elif name in ("scale-nan", "scale-negative", "scale-zero"):
        value = {"scale-nan": "NaN", "scale-negative": "-6553.5", "scale-zero": "0"}[name]
        (d / "cam_params.json").write_text('{"camera": {"w": 64, "h": 48, "fx": 50, "fy": 50, "cx": 31.5, '
                                           f'"cy": 23.5, "scale": {value}}}}}')
    elif name == "scale-string":
        (d / "cam_params.json").write_text('{"camera": {"w": 64, "h": 48, "fx": 50, "fy": 50, "cx": 31.5, '
                                           '"cy": 23.5, "scale": "x"}}')
    elif name == "traj-million-lines":
        (d / "traj.txt").write_text("1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\n" * 1_000_000)
    elif name == "traj-not-utf8":
        (d / "traj.txt").write_bytes(b"\xff" * 40 + b"\n")
    elif name == "traj-dev-zero":
        (d / "traj.txt").unlink()
        (d / "traj.txt").symlink_to("/dev/zero")
    else:
        raise AssertionError(name)


REPLICA_CASES = {"params-infinity": "Infinity", "params-deep": "nested", "params-1e400": "width",
                 "scale-nan": "NaN", "scale-negative": "-6553.5", "scale-zero": "got 0",
                 "scale-string": "'x'", "traj-million-lines": "lines", "traj-not-utf8": "not UTF-8",
                 "traj-dev-zero": "no frames found"}


@pytest.mark.parametrize("name", list(REPLICA_CASES))
def test_bad_replica_recording_is_one_line(name, tmp_path, capsys):
    src = WRITERS["replica"](tmp_path / "replica")
    _replica_case(name, src)
    out = tmp_path / "out"
    one_line_error(segment(src, out), capsys, REPLICA_CASES[name])
    assert not out.exists()


@pytest.mark.parametrize("value", ["nan", "inf", "-1", "0"])
def test_bad_depth_scale_option_is_one_line(value, seven, tmp_path, capsys):
    one_line_error(segment(seven, tmp_path / "out", "--depth-scale", value), capsys, "depth scale")


def _tum_case(name: str, d: Path) -> None:
    if name == "timestamp-only":
        (d / "rgb.txt").write_text("1000.000000\n1000.033333\n")
    elif name == "gt-timestamp-only":
        (d / "groundtruth.txt").write_text("1000.000000\n")
    elif name == "rgb-not-utf8":
        (d / "rgb.txt").write_bytes(b"1000.0 rgb/\xff.png\n")
    elif name == "gt-not-utf8":
        (d / "groundtruth.txt").write_bytes(b"\xff\xfe\n")
    elif name == "gt-fifo":
        (d / "groundtruth.txt").unlink()
        os.mkfifo(d / "groundtruth.txt")
    elif name == "timestamp-nan":
        (d / "depth.txt").write_text("nan depth/x.png\n")
    else:
        raise AssertionError(name)


TUM_CASES = {"timestamp-only": "timestamp and 1 more", "gt-timestamp-only": "timestamp and 7 more",
             "rgb-not-utf8": "not UTF-8", "gt-not-utf8": "not UTF-8", "gt-fifo": "not a regular file",
             "timestamp-nan": "finite number"}


@pytest.mark.parametrize("name", list(TUM_CASES))
def test_bad_tum_recording_is_one_line(name, tmp_path, capsys):
    src = WRITERS["tum"](tmp_path / "tum")
    _tum_case(name, src)
    one_line_error(segment(src, tmp_path / "out"), capsys, TUM_CASES[name])


def test_a_folder_matching_two_layouts_warns(seven, tmp_path, capsys):
    (seven / "rgb.txt").write_text("")
    (seven / "depth.txt").write_text("")
    assert run(segment(seven, tmp_path / "out")) == 0
    err = capsys.readouterr().err
    assert "warning" in err and "7scenes and tum" in err and "--layout" in err


# ---------------------------------------------------------------------------------- paths (2)
def test_paths_that_are_not_utf8_work(tmp_path, capsys):
    """A folder named with byte 0xff (Python: a surrogate escape) reached OpenCV as a str and
    segfaulted; now files are read and written by Python, OpenCV decodes from memory."""
    base = Path(os.fsdecode(bytes(tmp_path) + b"/x_\xff"))
    src = WRITERS["7scenes"](base / "rec")
    out = base / "out\udcfe"
    assert run(segment(src, out)) == 0, capsys.readouterr().err
    assert run(["build-map", str(out), "-o", str(base / "m\udcff.iesm")]) == 0, capsys.readouterr().err
    assert (base / "m\udcff.iesm").is_file()
    assert run(["view", str(base / "m\udcff.iesm"), "-o", str(base / "v\udcff.html")]) == 0, capsys.readouterr().err
    assert "\ufffd" in (base / "v\udcff.html").read_text(encoding="utf-8")  # the path, shown as text


# ------------------------------------------------------------------------------ segment -o (5)
def test_o_refuses_a_non_empty_folder_it_did_not_write(seven, tmp_path, capsys):
    victim = tmp_path / "home"
    victim.mkdir()
    (victim / "thesis.tex").write_text("years of work")
    one_line_error(segment(seven, victim), capsys, "not empty")
    one_line_error(segment(seven, victim, "--force"), capsys, "--force replaces only a frame directory")
    assert (victim / "thesis.tex").read_text() == "years of work"


@pytest.mark.parametrize("where", ["itself", "inside", "parent"])
def test_o_is_never_the_source(where, seven, tmp_path, capsys):
    out = {"itself": seven, "inside": seven / "out", "parent": tmp_path}[where]
    before = sorted(p.name for p in seven.iterdir())
    one_line_error(segment(seven, out, "--force"), capsys, "must not be the source")
    assert sorted(p.name for p in seven.iterdir()) == before


def test_o_file_and_symlink_are_refused_before_the_work(seven, tmp_path, capsys, monkeypatch):
    from iesm_agent.frames import convert

    def no_work(*_a, **_k):
        raise AssertionError("the recording was read before -o was checked")

    monkeypatch.setattr(convert, "import_recording", no_work)
    target = tmp_path / "file"
    target.write_text("keep")
    one_line_error(segment(seven, target), capsys, "not a directory")
    link = tmp_path / "link"
    link.symlink_to(tmp_path / "elsewhere", target_is_directory=True)
    one_line_error(segment(seven, link), capsys, "symbolic link")
    one_line_error(segment(seven, tmp_path / "missing" / "out"), capsys, "parent directory does not exist")
    assert target.read_text() == "keep"


def test_o_force_replaces_a_frame_directory_it_wrote(seven, tmp_path, capsys):
    out = tmp_path / "out"
    assert run(segment(seven, out)) == 0
    one_line_error(segment(seven, out), capsys, "not empty")
    assert run(segment(seven, out, "--force", "--every", "2")) == 0
    assert json.loads((out / "scene.json").read_text())["n_frames"] == 2


# ------------------------------------------------------------------------------ leftovers (9)
def test_a_killed_runs_staging_folder_is_removed_by_the_next_run(seven, tmp_path, capsys):
    out = tmp_path / "out"
    pid = 2 ** 22 + 12345  # above Linux's pid_max default: no such process
    stale = tmp_path / f".out.iesm-tmp.{pid}.abc123"
    (stale / "frames").mkdir(parents=True)
    (stale / "frames" / "000000.rgb.png").write_bytes(b"x" * 1000)
    live = tmp_path / f".out.iesm-tmp.{os.getpid()}.live"  # ours: a write in progress, left alone
    live.mkdir()
    assert run(segment(seven, out)) == 0
    assert not stale.exists() and live.exists()


def test_the_staging_folder_names_the_process(seven, tmp_path, monkeypatch):
    from iesm_agent.fileio import staged_directory

    with staged_directory(tmp_path / "out") as stage:
        assert stage.name.startswith(f".out.iesm-tmp.{os.getpid()}.")
    assert (tmp_path / "out").is_dir()


# ------------------------------------------------------------------------------ seeded fuzzing
def _mutate(rng: random.Random, src: Path) -> str:
    """Damage one file of the recording `src` at random; returns what was done."""
    files = sorted(p for p in src.rglob("*") if p.is_file())
    victim = rng.choice(files)
    kind = rng.choice(["bytes", "truncate", "empty", "numbers", "delete", "bomb", "swap"])
    data = victim.read_bytes()
    if kind == "bytes" and data:
        raw = bytearray(data)
        for _ in range(rng.randint(1, 16)):
            raw[rng.randrange(len(raw))] = rng.randrange(256)
        victim.write_bytes(bytes(raw))
    elif kind == "truncate":
        victim.write_bytes(data[:rng.randrange(max(len(data), 1))])
    elif kind == "empty":
        victim.write_bytes(b"")
    elif kind == "numbers" and victim.suffix in (".txt", ".json"):
        words = data.decode("utf-8", "replace").split(" ")
        if words:
            i = rng.randrange(len(words))
            words[i] = rng.choice(["nan", "inf", "-inf", "1e308", "-1e308", "1e400", "0", "-1", "NaN", "Infinity",
                                   "1e30", "x", ""])
        victim.write_text(" ".join(words))
    elif kind == "delete":
        victim.unlink()
    elif kind == "bomb" and victim.suffix in (".png", ".jpg"):
        side = rng.choice([5000, 20000, 65535])
        victim.write_bytes(png_claiming(side, side) if victim.suffix == ".png" else jpeg_claiming(side, side))
    elif kind == "swap" and len(files) > 1:
        other = rng.choice(files)
        victim.write_bytes(other.read_bytes())
    return f"{kind}:{victim.suffix or victim.name}"


def _fuzz(layout: str, n: int, seed: int, tmp_path: Path, capsys) -> None:
    rng = random.Random(seed)
    base = WRITERS[layout](tmp_path / f"base-{layout}")
    for case in range(n):
        src = tmp_path / f"{layout}-{case}"
        shutil.copytree(base, src, symlinks=True)
        what = _mutate(rng, src)
        extra = ["--skip-bad-frames"] if rng.random() < 0.3 else []
        out = tmp_path / "out"
        code = check_cli(segment(src, out, *extra), capsys, outputs=(out,))
        Tally.add(f"recording {layout}", f"{what.split(':')[0]}:{'refused' if code == 2 else 'accepted'}")
        shutil.rmtree(src)


@pytest.mark.parametrize("layout", ["7scenes", "replica", "scannet"])
def test_fuzz_recordings(layout, tmp_path, capsys):
    _fuzz(layout, FAST // 2, 31, tmp_path, capsys)


@pytest.mark.slow
@pytest.mark.parametrize("layout", ["7scenes", "replica", "scannet", "tum"])
def test_fuzz_recordings_seeded_long_run(layout, tmp_path, capsys):
    _fuzz(layout, SLOW // 8, 3100, tmp_path, capsys)


# ------------------------------------------------------------------------------ the readers themselves
@pytest.mark.parametrize("ext, params", [(".png", []), (".jpg", []), (".jpg", [1, 90, 2, 1]), (".png", [16, 9])])
def test_image_header_gives_the_size_opencv_decodes(ext, params):
    """`fileio.image_header` reads the size from the header alone (PNG IHDR; JPEG baseline and
    progressive SOF) as OpenCV decodes it, for odd sizes and channel counts."""
    import cv2

    from iesm_agent.fileio import image_header

    rng = np.random.default_rng(5)
    for h, w, c in [(1, 1, 1), (7, 300, 3), (480, 640, 3), (33, 17, 1)]:
        image = rng.integers(0, 255, (h, w, c) if c > 1 else (h, w), dtype=np.uint8)
        data = cv2.imencode(ext, image, params)[1].tobytes()
        kind, width, height = image_header(data)
        assert (kind, width, height) == ("png" if ext == ".png" else "jpeg", w, h)
        assert cv2.imdecode(np.frombuffer(data, np.uint8), cv2.IMREAD_UNCHANGED).shape[:2] == (height, width)
    for junk in (b"", b"\x89PNG\r\n\x1a\n", b"\xff\xd8\xff", b"BM\x00\x00", b"GIF89a", b"\xff\xd8" + b"\x00" * 40):
        with pytest.raises(ValueError):
            image_header(junk)


def test_read_bytes_refuses_what_is_not_a_bounded_regular_file(tmp_path):
    from iesm_agent.errors import IesmError
    from iesm_agent.fileio import read_bytes, read_text

    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    big = tmp_path / "big"
    big.write_bytes(b"x" * 101)
    lines = tmp_path / "lines"
    lines.write_text("a\n" * 11)
    for path, needle in [(fifo, "not a regular file"), (Path("/dev/zero"), "not a regular file"),
                         (tmp_path, "not a regular file"), (tmp_path / "none", "missing"), (big, "more than the 100")]:
        with pytest.raises(IesmError, match=needle):
            read_bytes(path, 100)
    with pytest.raises(IesmError, match="more than the 10 lines"):
        read_text(lines, max_lines=10)
    assert read_text(lines, max_lines=11) == "a\n" * 11


@pytest.mark.slow
def test_kill_9_mid_segment_leaves_nothing_the_next_run_keeps(tmp_path, capsys):
    """Issue 31 (9) for real: `iesm segment` killed with SIGKILL while its staging folder exists;
    the next run that writes the same -o removes the leftover (its process is gone)."""
    import signal
    import subprocess
    import sys
    import time

    src = WRITERS["7scenes"](tmp_path / "rec", n=60)
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "iesm_agent.cli", *segment(src, out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env={**os.environ, "HF_HUB_OFFLINE": "1"})
    deadline = time.monotonic() + 120
    while not list(tmp_path.glob(".out.iesm-tmp.*/frames/*.png")) and time.monotonic() < deadline:
        assert proc.poll() is None, "segment ended before it could be killed"
        time.sleep(0.01)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    left = list(tmp_path.glob(".out.iesm-tmp.*"))
    assert left and f".{proc.pid}." in left[0].name  # the leftover names the dead process
    assert run(segment(src, out)) == 0, capsys.readouterr().err
    assert not list(tmp_path.glob(".out.iesm-tmp.*")) and json.loads((out / "scene.json").read_text())["n_frames"] == 60
