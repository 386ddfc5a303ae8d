"""Instance captioning (paper Sec. 3.3): keyframes per instance, crops, a captioner (offline:
pixels and geometry; vision: a vision-LLM prompt per keyframe plus an aggregation prompt) and
the captions, tags and rooms written into the map."""

from .offline import OfflineCaptioner
from .pipeline import Captioner, caption_map, strip_captions
from .schema import CaptionReply, CaptionResult, CaptionTags
from .vision import VisionCaptioner

__all__ = ["CaptionReply", "CaptionResult", "CaptionTags", "Captioner", "OfflineCaptioner",
           "VisionCaptioner", "caption_map", "strip_captions"]
