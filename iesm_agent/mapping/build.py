"""The mapping pipeline over a frame set (paper Sec. 3.1): per frame, project the candidates
top-down, associate and fuse them into the instance dictionary; then the optional second
pass, the continuity merge (`MappingConfig.continuity_gap`, off in `paper()`), categorisation
against the scene's category list, and the 2.5D `SceneMap`."""

from __future__ import annotations

from typing import Callable, Optional

import numpy as np

from ..config import MappingConfig
from ..errors import IesmError
from ..frames import Frame, FrameSet, Intrinsics, Segmentation, Segmenter
from ..store.model import SceneMap
from .clean import clean_masks, smooth_depth
from .dictionary import InstanceDictionary
from .project import project_candidates
from .tops import fill_tops

TEXT_SPACES = ("all-MiniLM-L6-v2", "hash-384")  # spaces `text_vectors` embeds categories in
UNLABELLED = "object"  # the label of instances from a segmenter without categories


class MapBuilder:
    """Incremental builder: `add(frame, segmentation)` per frame, then `finish(...)`."""

    def __init__(self, intrinsics: Intrinsics, cfg: MappingConfig | None = None):
        self.intrinsics = intrinsics
        self.cfg = cfg or MappingConfig()
        self.dictionary: InstanceDictionary | None = None
        self.n_frames = 0

    def add(self, frame: Frame, seg: Segmentation) -> None:
        """Project, associate and fuse one frame's candidates."""
        k, cfg = self.intrinsics, self.cfg
        depth = (smooth_depth(frame.depth, cfg.depth_smooth_px, cfg.depth_smooth_disparity) if cfg.depth_smooth_px
                 else frame.depth)
        masks = clean_masks(seg.masks, depth, erode_px=cfg.mask_erode_px, edge_jump=cfg.depth_edge_jump,
                            min_pixels=cfg.min_mask_pixels)
        if cfg.top_fill_max_cos is not None:
            depth = fill_tops(depth, masks, k.fx, k.fy, k.cx, k.cy, frame.pose, max_cos=cfg.top_fill_max_cos,
                              max_ratio=cfg.top_fill_max_ratio, min_readings=cfg.min_mask_pixels)
        cands = project_candidates(depth, masks, k.fx, k.fy, k.cx, k.cy, frame.pose, cfg.cell_size,
                                   min_pixels=cfg.min_mask_pixels, max_depth=cfg.max_depth,
                                   min_cell_points=cfg.min_cell_points)
        if self.dictionary is None:
            self.dictionary = InstanceDictionary(seg.embeddings.shape[1], self.cfg)
        elif seg.embeddings.shape[1] != self.dictionary.embeddings.shape[1]:
            raise IesmError(f"embedding dimension {seg.embeddings.shape[1]} differs from earlier frames "
                            f"({self.dictionary.embeddings.shape[1]})", f"frame {frame.index}")
        self.dictionary.integrate(cands, seg.embeddings, seg.scores, frame.index)
        self.n_frames += 1

    def finish(self, categories: list[str], category_embeddings: np.ndarray, *, scene_id: str,
               embedding_space: str, second_pass: bool = True) -> SceneMap:
        """The built map; `category_embeddings` (J, D) rows align with `categories`."""
        from .scene import to_scene_map

        d = self.dictionary or InstanceDictionary(category_embeddings.shape[1], self.cfg)
        before, merges = len(d), 0
        d = d.reliable_footprints(self.cfg.reliable_depth)
        if second_pass:
            d, merges = d.second_pass()
        d, continuous = d.merge_continuous()
        meta = {"frames": str(self.n_frames), "second_pass": str(second_pass).lower(),
                "instances_first_pass": str(before), "second_pass_merges": str(merges),
                "continuity_merges": str(continuous)}
        return to_scene_map(d, categories, category_embeddings, cfg=self.cfg, scene_id=scene_id,
                            embedding_space=embedding_space, meta=meta)


def category_vectors(frames: FrameSet) -> tuple[list[str], np.ndarray | None]:
    """The scene's category list and its text embeddings E (J, D), in the masks' embedding space:
    from DIR/vocabulary.npz when the segmenter wrote one (its own text tower), else embedded with
    `text_vectors`. A space with no text tower and no categories (the geometric segmenter) gives
    (["object"], None): every instance is an "object"."""
    from ..embeddings import text_vectors

    vocab = frames.vocabulary()
    if vocab is not None and len(vocab["names"]):
        return [str(n) for n in vocab["names"]], vocab["embeddings"].astype(np.float32)
    categories = list(frames.meta.categories)
    if not categories:
        if frames.meta.embedding_space in TEXT_SPACES:
            raise IesmError("scene.json has an empty 'categories' list (needed to label instances)",
                            frames.directory / "scene.json", "categories")
        return [UNLABELLED], None
    e, _space = text_vectors(categories, frames.meta.embedding_space)
    return categories, e


def build_map(frames: FrameSet, cfg: MappingConfig | None = None, *, second_pass: bool = True,
              segmenter: Optional[Segmenter] = None,
              on_frame: Callable[[int], None] | None = None) -> SceneMap:
    """Build the 2.5D map of `frames`. Masks come from each frame's seg.npz, or from `segmenter`
    when given. Any unreadable frame raises `IesmError` naming the file before anything is written."""
    cfg = cfg or MappingConfig()
    if cfg.cell_size != frames.meta.cell_size and "cell_size" not in cfg.model_fields_set:
        cfg = cfg.model_copy(update={"cell_size": frames.meta.cell_size})
    categories, e = category_vectors(frames)
    builder = MapBuilder(frames.intrinsics, cfg)
    for i in range(len(frames)):
        frame = frames.read(i)
        seg = segmenter.segment(frame) if segmenter is not None else frame.segmentation
        if seg is None:
            raise IesmError("segmentation file is missing (or pass a segmenter)", frames.path(i, "seg.npz"))
        if e is None:
            e = np.zeros((1, seg.embeddings.shape[1]), np.float32)  # no categories: all "object"
        if seg.embeddings.shape[1] != e.shape[1]:
            raise IesmError(f"mask embeddings have dimension {seg.embeddings.shape[1]}, the scene's embedding "
                            f"space {frames.meta.embedding_space!r} has {e.shape[1]}", frames.path(i, "seg.npz"))
        builder.add(frame, seg)
        if on_frame is not None:
            on_frame(i)
    if e is None:
        e = np.zeros((1, 1), np.float32)
    return builder.finish(categories, e, scene_id=frames.meta.scene_id,
                          embedding_space=frames.meta.embedding_space, second_pass=second_pass)
