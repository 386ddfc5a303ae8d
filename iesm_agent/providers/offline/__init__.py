"""The deterministic rule-based `OfflineModel`: reads rendered prompts, answers like an LLM."""

from .model import OfflineModel

__all__ = ["OfflineModel"]
