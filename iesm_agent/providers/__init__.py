"""Chat model providers: the protocol (`base`), the offline rule-based model, OpenAI-compatible
endpoints and the response cache."""

from .base import Capabilities, ChatOptions, Completion, ImagePart, Message, Model, TextPart, Usage
from .cache import CachedModel
from .function_model import FunctionModel
from .registry import ENTRY_POINT_GROUP, get_model, providers, register_provider

__all__ = ["Capabilities", "CachedModel", "ChatOptions", "Completion", "ENTRY_POINT_GROUP",
           "FunctionModel", "ImagePart", "Message", "Model", "TextPart", "Usage", "get_model",
           "providers", "register_provider"]
