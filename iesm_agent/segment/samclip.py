"""`sam-clip`: class-agnostic masks from Segment Anything and one CLIP embedding per mask crop
(ConceptGraphs' recipe). Built from a `SegmenterSpec`; models load once per segmenter (one per Ray
actor). Nothing is downloaded: SAM needs a checkpoint path, CLIP a checkpoint path or a tag already
in the user's cache, unless `random_weights` (tests: same code, randomly initialised models).

Embeddings (K, D) float32 L2-normalised in the space `space` ("open_clip:<model>:<weights>");
`text_embeddings(names)` embeds category / room names with the same model's text tower
("a photo of a {name}."); `frame_feature(frame)` the whole image (D,) for room labels."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import IesmError
from ..frames import Frame, Segmentation
from . import SegmenterSpec

#: small SAM image encoder for tests (random weights): embed dim, depth, heads, global attention
TINY_SAM = (64, 2, 2, [1])
CROP_PAD = 10  # px around a mask's bounding box


def _device(spec: SegmenterSpec) -> str:
    import torch

    return spec.device or ("cuda" if torch.cuda.is_available() else "cpu")


def build_sam(spec: SegmenterSpec):
    """The SAM model of `spec` (eval mode, on its device)."""
    import torch
    from segment_anything import sam_model_registry
    from segment_anything.build_sam import _build_sam

    ckpt = spec.sam_checkpoint
    if ckpt is None and not spec.random_weights:
        raise IesmError("sam-clip needs a SAM checkpoint (--sam-checkpoint sam_vit_h_4b8939.pth)", None,
                        "--sam-checkpoint")
    if ckpt is not None and not Path(ckpt).is_file():
        raise IesmError("SAM checkpoint file is missing", ckpt)
    torch.manual_seed(spec.seed)
    if spec.sam_model == "tiny":
        dim, depth, heads, glob = TINY_SAM
        model = _build_sam(encoder_embed_dim=dim, encoder_depth=depth, encoder_num_heads=heads,
                           encoder_global_attn_indexes=glob, checkpoint=ckpt)
    elif spec.sam_model in sam_model_registry and spec.sam_model != "default":
        model = sam_model_registry[spec.sam_model](checkpoint=ckpt)
    else:
        raise IesmError(f"unknown SAM model {spec.sam_model!r} (vit_h, vit_l, vit_b, tiny)", None, "--sam-model")
    return model.to(_device(spec)).eval()


def build_clip(spec: SegmenterSpec):
    """(model, preprocess, tokenizer) of open_clip for `spec` (eval mode, on its device)."""
    import open_clip
    import torch

    if spec.clip_config is not None:
        if not Path(spec.clip_config).is_file():
            raise IesmError("CLIP model config file is missing", spec.clip_config)
        open_clip.add_model_config(spec.clip_config)
    if spec.clip_pretrained is None and not spec.random_weights:
        raise IesmError("sam-clip needs CLIP weights (--clip-pretrained PATH or a cached tag)", None,
                        "--clip-pretrained")
    if spec.clip_model not in open_clip.list_models():
        raise IesmError(f"unknown open_clip model {spec.clip_model!r}", None, "--clip-model")
    torch.manual_seed(spec.seed + 1)
    model, _, preprocess = open_clip.create_model_and_transforms(spec.clip_model, pretrained=spec.clip_pretrained,
                                                                 device=_device(spec))
    return model.eval(), preprocess, open_clip.get_tokenizer(spec.clip_model)


def text_embeddings(clip, tokenizer, device: str, names: list[str]) -> np.ndarray:
    """(J, D) float32 L2-normalised CLIP text embeddings of `names` ("a photo of a {name}.")."""
    import torch

    tokens = tokenizer([f"a photo of a {n}." for n in names]).to(device)
    with torch.no_grad():
        f = clip.encode_text(tokens).float()
    return torch.nn.functional.normalize(f, dim=-1).cpu().numpy().astype(np.float32)


class ClipText:
    """The text tower alone (the Ray driver embeds the vocabulary without loading SAM)."""

    def __init__(self, spec: SegmenterSpec):
        self.device = _device(spec)
        self.clip, _preprocess, self.tokenizer = build_clip(spec)

    def text_embeddings(self, names: list[str]) -> np.ndarray:
        return text_embeddings(self.clip, self.tokenizer, self.device, names)


class SamClipSegmenter:
    """`segment(frame) -> Segmentation` with SAM masks and CLIP crop embeddings."""

    name = "sam-clip"

    def __init__(self, spec: SegmenterSpec):
        import torch
        from segment_anything import SamAutomaticMaskGenerator

        if spec.threads:
            torch.set_num_threads(spec.threads)
        self.spec = spec
        self.device = _device(spec)
        self.sam = build_sam(spec)
        self.generator = SamAutomaticMaskGenerator(
            self.sam, points_per_side=spec.points_per_side, pred_iou_thresh=spec.pred_iou_thresh,
            stability_score_thresh=spec.stability_score_thresh, min_mask_region_area=spec.min_mask_area)
        self.clip, self.preprocess, self.tokenizer = build_clip(spec)
        weights = spec.clip_pretrained if spec.clip_pretrained else f"random-seed{spec.seed}"
        self.space = f"open_clip:{spec.clip_model}:{Path(weights).name}"

    def _encode_images(self, images: list[np.ndarray]) -> np.ndarray:
        import torch
        from PIL import Image

        if not images:
            return np.zeros((0, self.dim), np.float32)
        batch = torch.stack([self.preprocess(Image.fromarray(im)) for im in images]).to(self.device)
        with torch.no_grad():
            f = self.clip.encode_image(batch).float()
        return torch.nn.functional.normalize(f, dim=-1).cpu().numpy().astype(np.float32)

    @property
    def dim(self) -> int:
        return int(self.text_embeddings(["x"]).shape[1])

    def segment(self, frame: Frame) -> Segmentation:
        import torch

        with torch.no_grad():
            records = self.generator.generate(np.ascontiguousarray(frame.rgb))
        records.sort(key=lambda r: (-int(r["area"]), r["bbox"]))
        h, w = frame.depth.shape
        masks = np.stack([r["segmentation"] for r in records]) if records else np.zeros((0, h, w), bool)
        crops = []
        for r in records:
            x, y, bw, bh = (int(v) for v in r["bbox"])
            crops.append(frame.rgb[max(0, y - CROP_PAD):min(h, y + bh + CROP_PAD),
                                   max(0, x - CROP_PAD):min(w, x + bw + CROP_PAD)])
        crops = [c if c.size else frame.rgb for c in crops]
        emb = self._encode_images(crops)
        scores = np.clip(np.array([r["predicted_iou"] for r in records], np.float32), 0.0, 1.0)
        return Segmentation(masks.astype(bool), emb, scores)

    def text_embeddings(self, names: list[str]) -> np.ndarray:
        """(J, D) float32 L2-normalised text embeddings of `names` ("a photo of a {name}.")."""
        return text_embeddings(self.clip, self.tokenizer, self.device, names)

    def frame_feature(self, frame: Frame) -> np.ndarray:
        """(D,) float32 L2-normalised CLIP embedding of the whole frame."""
        return self._encode_images([frame.rgb])[0]
