"""Goal retrieval (MTEFR, paper Sec. 3.4.2): candidate selection, gate + expert LLMs, score fusion."""

from .fusion import FusionResult, fuse
from .result import CallTrace, RetrievalResult
from .retriever import Retriever

__all__ = ["CallTrace", "FusionResult", "RetrievalResult", "Retriever", "fuse"]
