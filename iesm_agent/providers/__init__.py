"""Chat model providers: the protocol (`base`), the offline rule-based model, OpenAI-compatible
endpoints and the response cache."""

from .base import Capabilities, ChatOptions, Completion, ImagePart, Message, Model, TextPart, Usage
from .function_model import FunctionModel
from .registry import ENTRY_POINT_GROUP, get_model, providers, register_provider



def __getattr__(name: str):
    """`CachedModel` is imported on first use (diskcache and sqlite cost start-up time)."""
    if name == "CachedModel":
        from .cache import CachedModel

        return CachedModel
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["Capabilities", "CachedModel", "ChatOptions", "Completion", "ENTRY_POINT_GROUP",
           "FunctionModel", "ImagePart", "Message", "Model", "TextPart", "Usage", "get_model",
           "providers", "register_provider"]
