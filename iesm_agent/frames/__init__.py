"""RGB-D frames: our own frame-directory layout (`ours`: what `iesm build-map` reads) and readers
for the layouts recordings come in (7-Scenes / 3DMatch, Replica as NICE-SLAM lays it out, ScanNet
exports, TUM RGB-D), with depth and pose checks and gravity alignment, converted into ours by
`convert.import_recording`. See docs/frames.md."""

from .ours import (DEPTH_SCALE, FORMAT, MAX_DEPTH_M, VERSION, Frame, FrameSet, Intrinsics, SceneMeta,
                   Segmentation, Segmenter, encode_segmentation, frame_stem, write_frame, write_frame_features,
                   write_frame_set, write_segmentation, write_vocabulary)
from .recording import FrameRef, Recording, SkipLog
from .detect import LAYOUTS, detect_layout, matching_layouts, open_recording

__all__ = ["DEPTH_SCALE", "FORMAT", "MAX_DEPTH_M", "VERSION", "Frame", "FrameSet", "Intrinsics", "SceneMeta",
           "Segmentation", "Segmenter", "encode_segmentation", "frame_stem", "write_frame", "write_frame_features",
           "write_frame_set", "write_segmentation", "write_vocabulary", "FrameRef", "Recording", "SkipLog",
           "LAYOUTS", "detect_layout", "matching_layouts", "open_recording"]
