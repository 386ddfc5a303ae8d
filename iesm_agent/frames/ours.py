"""RGB-D frame sets on disk: the layout `iesm sim` writes and `iesm build-map` reads.

DIR/scene.json, DIR/intrinsics.json, DIR/frames/NNNNNN.{rgb.png, depth.png, pose.txt, seg.npz,
inst.png}, optional DIR/vocabulary.npz and DIR/frame_features.npz (written by `iesm segment`); see
docs/frames.md. Simulator ground truth (DIR/gt/) is read by `sim.ground_truth`.
Units: metres, world z up with the floor at z = 0; camera frame OpenCV (x right, y down, z forward);
poses are camera-to-world 4x4; depth png is uint16 millimetres along the optical axis, 0 = none.
PNG I/O uses OpenCV (the `mapping` extra). Every bad file gives an `IesmError` naming it.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Literal, Optional, Protocol

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from ..errors import IesmError
from ..store.model import Count
from ..fileio import atomic_write, read_image, read_json_model, read_npz, read_text, write_png, write_text

FORMAT = "iesm-frames"
VERSION = 1
DEPTH_SCALE = 1000.0  # depth png units per metre (millimetres)
MAX_DEPTH_M = 65.535  # largest depth a uint16 millimetre png can hold
MAX_TRANSLATION_M = 10_000.0  # a camera farther from the origin is a corrupt pose (m)
MAX_POSE_BYTES = 64 * 1024  # largest pose.txt read


class Intrinsics(BaseModel):
    """Pinhole intrinsics in pixels for (height, width) images."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    width: int = Field(gt=0)
    height: int = Field(gt=0)
    fx: float = Field(gt=0)
    fy: float = Field(gt=0)
    cx: float
    cy: float

    def matrix(self) -> np.ndarray:
        """The 3x3 camera matrix K."""
        return np.array([[self.fx, 0.0, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]])


class SceneMeta(BaseModel):
    """scene.json: `embedding_space` names the text-embedding space of the mask embeddings
    ("all-MiniLM-L6-v2" or "hash-384"); `categories` is the open vocabulary; `cell_size` (m) the
    suggested top-down grid resolution."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    format: Literal["iesm-frames"] = FORMAT
    version: Literal[1] = VERSION
    scene_id: str = Field(min_length=1)
    n_frames: Count
    embedding_space: str = Field(min_length=1)
    categories: list[str] = Field(default_factory=list)
    cell_size: float = Field(default=0.05, gt=0)
    #: where the frames came from and what was done to them (layout, gravity alignment, skipped
    #: frames), written by `iesm segment` for recordings in other layouts; None for our own
    source: Optional[dict[str, str]] = None


@dataclass
class Segmentation:
    """Candidate masks of one frame: `masks` (K, H, W) bool, `embeddings` (K, D) float32
    L2-normalised, `scores` (K,) float32 mask confidence in [0, 1]."""

    masks: np.ndarray
    embeddings: np.ndarray
    scores: np.ndarray

    def __post_init__(self) -> None:
        k = len(self.masks)
        if self.masks.ndim != 3 or self.embeddings.ndim != 2 or self.scores.shape != (k,) \
                or len(self.embeddings) != k:
            raise ValueError(f"segmentation arrays disagree: masks {self.masks.shape}, "
                             f"embeddings {self.embeddings.shape}, scores {self.scores.shape}")


@dataclass
class Frame:
    """One RGB-D frame: `rgb` (H, W, 3) uint8; `depth` (H, W) float32 metres, 0 = no reading;
    `pose` (4, 4) float64 camera-to-world; optional `segmentation` and ground-truth
    `instance_ids` (H, W) int32 (0 = none)."""

    index: int
    rgb: np.ndarray
    depth: np.ndarray
    pose: np.ndarray
    segmentation: Optional[Segmentation] = None
    instance_ids: Optional[np.ndarray] = None


class Segmenter(Protocol):
    """Turns a frame into candidate masks + embeddings (a real model, or the simulator's
    synthetic one that reads `frame.instance_ids`)."""

    def segment(self, frame: Frame) -> Segmentation: ...


def frame_stem(index: int) -> str:
    return f"{index:06d}"


# ---------------------------------------------------------------------------------------- writing


def write_frame_set(directory: str | Path, meta: SceneMeta, intrinsics: Intrinsics) -> None:
    """Create DIR/frames and write scene.json and intrinsics.json."""
    directory = Path(directory)
    (directory / "frames").mkdir(parents=True, exist_ok=True)
    write_text(directory / "scene.json", meta.model_dump_json(indent=1, exclude_none=True))
    write_text(directory / "intrinsics.json", intrinsics.model_dump_json(indent=1))


def write_frame(directory: str | Path, frame: Frame) -> None:
    """Write one frame's files under DIR/frames (seg.npz and inst.png only when present)."""
    import cv2

    base = Path(directory) / "frames"
    stem = frame_stem(frame.index)
    write_png(base / f"{stem}.rgb.png", cv2.cvtColor(np.ascontiguousarray(frame.rgb, np.uint8), cv2.COLOR_RGB2BGR))
    depth_mm = np.rint(np.clip(frame.depth, 0.0, MAX_DEPTH_M) * DEPTH_SCALE).astype(np.uint16)
    write_png(base / f"{stem}.depth.png", depth_mm)
    write_text(base / f"{stem}.pose.txt",
                "\n".join(" ".join(f"{v:.9g}" for v in row) for row in np.asarray(frame.pose)) + "\n")
    if frame.segmentation is not None:
        write_segmentation(base / f"{stem}.seg.npz", encode_segmentation(frame.segmentation))
    if frame.instance_ids is not None:
        if frame.instance_ids.max(initial=0) > np.iinfo(np.uint16).max:
            raise IesmError("instance ids above 65535 do not fit a uint16 png", base / f"{stem}.inst.png")
        write_png(base / f"{stem}.inst.png", frame.instance_ids.astype(np.uint16))


def encode_segmentation(seg: Segmentation) -> bytes:
    """The bytes of a seg.npz (np.savez_compressed, no pickles); the serial and the Ray paths of
    `iesm segment` both write these, so their files are byte-comparable."""
    import io

    buffer = io.BytesIO()
    np.savez_compressed(buffer, masks=seg.masks.astype(bool), embeddings=seg.embeddings.astype(np.float32),
                        scores=seg.scores.astype(np.float32))
    return buffer.getvalue()


def write_segmentation(path: str | Path, data: bytes) -> None:
    """Write encoded seg.npz bytes atomically."""
    atomic_write(Path(path), lambda p: Path(p).write_bytes(data))


def write_vocabulary(directory: str | Path, names: list[str], embeddings: np.ndarray,
                     room_names: list[str] = (), room_embeddings: np.ndarray | None = None) -> None:
    """DIR/vocabulary.npz: the category list `names` (J,) and its text embeddings (J, D) float32
    in the masks' embedding space (made by the segmenter's own text tower, so `iesm build-map`
    needs no model), optionally room names (R,) and their embeddings (R, D)."""
    rooms = np.zeros((0, embeddings.shape[1]), np.float32) if room_embeddings is None else room_embeddings
    atomic_write(Path(directory) / "vocabulary.npz", lambda p: np.savez_compressed(
        p, names=np.array(list(names), dtype=str), embeddings=np.asarray(embeddings, np.float32),
        room_names=np.array(list(room_names), dtype=str), room_embeddings=np.asarray(rooms, np.float32)))


def write_frame_features(directory: str | Path, features: np.ndarray) -> None:
    """DIR/frame_features.npz: `features` (N, D) float32, one L2-normalised image embedding per
    frame (CLIP frame features for per-cell room labels)."""
    atomic_write(Path(directory) / "frame_features.npz",
                 lambda p: np.savez_compressed(p, features=np.asarray(features, np.float32)))


# ---------------------------------------------------------------------------------------- reading


def _read_pose(path: Path) -> np.ndarray:
    rows = [line.split() for line in read_text(path, max_bytes=MAX_POSE_BYTES).split("\n") if line.strip()]
    try:
        pose = np.array([[float(v) for v in row] for row in rows], dtype=np.float64) \
            if all(len(r) == 4 for r in rows) else None
    except ValueError:
        raise IesmError("pose must be 4 lines of 4 numbers", path) from None
    if pose is None or pose.shape != (4, 4):
        raise IesmError(f"pose must be a 4x4 matrix, got {len(rows)} lines of "
                        f"{sorted({len(r) for r in rows})} numbers", path)
    if not np.all(np.isfinite(pose)) or not np.allclose(pose[3], [0, 0, 0, 1], atol=1e-6):
        raise IesmError("pose must be finite with last row 0 0 0 1", path)
    if np.abs(pose[:3, 3]).max() > MAX_TRANSLATION_M or np.abs(pose[:3, :3]).max() > 1.0 + 1e-3:
        raise IesmError(f"pose must be a rotation (entries within +-1) and a translation within "
                        f"+-{MAX_TRANSLATION_M:g} m", path)
    return pose


def _read_segmentation(path: Path, hw: tuple[int, int]) -> Segmentation:
    def check(name: str, shape: tuple[int, ...], dtype) -> None:  # before the array is read
        if name == "masks" and (len(shape) != 3 or shape[1:] != hw):
            raise IesmError(f"masks have shape {shape}, frame is {hw}", path)

    data = read_npz(path, ("masks", "embeddings", "scores"), check=check,
                     kinds={"masks": "bu", "embeddings": "f", "scores": "f"})
    masks, embeddings, scores = data["masks"], data["embeddings"], data["scores"]
    if not np.all(np.isfinite(embeddings)):
        raise IesmError("embeddings must be finite (NaN or infinity found)", path)
    if not np.all((scores >= 0) & (scores <= 1)):  # False for NaN
        raise IesmError("scores must lie in [0, 1] (NaN or out of range found)", path)
    if masks.dtype.kind == "u" and masks.size and masks.max() > 1:
        raise IesmError("masks must be boolean (0 or 1)", path)
    try:
        return Segmentation(masks.astype(bool, copy=False), embeddings.astype(np.float32, copy=False),
                            scores.astype(np.float32, copy=False))
    except ValueError as exc:
        raise IesmError(str(exc), path) from None


class FrameSet:
    """A frame directory opened for reading; `read(i)` loads frame i, iteration yields all."""

    def __init__(self, directory: Path, meta: SceneMeta, intrinsics: Intrinsics):
        self.directory = directory
        self.meta = meta
        self.intrinsics = intrinsics

    @classmethod
    def open(cls, directory: str | Path) -> "FrameSet":
        directory = Path(directory)
        if not directory.is_dir():
            raise IesmError("not a frame directory", directory)
        meta = read_json_model(directory / "scene.json", SceneMeta)
        intrinsics = read_json_model(directory / "intrinsics.json", Intrinsics)
        return cls(directory, meta, intrinsics)  # type: ignore[arg-type]

    def __len__(self) -> int:
        return self.meta.n_frames

    def __iter__(self) -> Iterator[Frame]:
        return (self.read(i) for i in range(len(self)))

    def path(self, index: int, kind: str) -> Path:
        """Path of one frame file; `kind` is rgb.png, depth.png, pose.txt, seg.npz or inst.png."""
        return self.directory / "frames" / f"{frame_stem(index)}.{kind}"

    def vocabulary(self) -> Optional[dict[str, np.ndarray]]:
        """DIR/vocabulary.npz as arrays (names, embeddings, room_names, room_embeddings), or None."""
        path = self.directory / "vocabulary.npz"
        if not path.is_file():
            return None
        data = read_npz(path, ("names", "embeddings", "room_names", "room_embeddings"), kinds="biufU")
        if data["embeddings"].ndim != 2 or len(data["embeddings"]) != len(data["names"]):
            raise IesmError(f"{len(data['names'])} names but embeddings of shape {data['embeddings'].shape}", path)
        return data

    def frame_features(self) -> Optional[np.ndarray]:
        """DIR/frame_features.npz `features` (N, D) float32, or None when absent."""
        path = self.directory / "frame_features.npz"
        if not path.is_file():
            return None
        features = read_npz(path, ("features",), kinds="biufU")["features"]
        if features.ndim != 2 or len(features) != len(self):
            raise IesmError(f"features have shape {features.shape}, the set has {len(self)} frames", path)
        return features.astype(np.float32, copy=False)

    def read(self, index: int) -> Frame:
        if not 0 <= index < len(self):
            raise IndexError(f"frame {index} out of range (0..{len(self) - 1})")
        hw = (self.intrinsics.height, self.intrinsics.width)
        rgb = read_image(self.path(index, "rgb.png"), color=True)
        depth_raw = read_image(self.path(index, "depth.png"), color=False)
        for path, image in ((self.path(index, "rgb.png"), rgb), (self.path(index, "depth.png"), depth_raw)):
            if image.shape[:2] != hw:
                raise IesmError(f"image is {image.shape[:2]}, intrinsics.json says {hw}", path)
        if depth_raw.ndim != 2 or depth_raw.dtype != np.uint16:
            raise IesmError("depth must be a single-channel 16-bit png in millimetres", self.path(index, "depth.png"))
        pose = _read_pose(self.path(index, "pose.txt"))
        seg_path, inst_path = self.path(index, "seg.npz"), self.path(index, "inst.png")
        segmentation = _read_segmentation(seg_path, hw) if seg_path.is_file() else None
        instance_ids = None
        if inst_path.is_file():
            inst = read_image(inst_path, color=False)
            if inst.shape != hw:
                raise IesmError(f"instance image is {inst.shape}, frame is {hw}", inst_path)
            instance_ids = inst.astype(np.int32)
        return Frame(index=index, rgb=rgb, depth=depth_raw.astype(np.float32) / DEPTH_SCALE, pose=pose,
                     segmentation=segmentation, instance_ids=instance_ids)

