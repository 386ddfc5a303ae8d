"""Model specs (`offline`, `openai:<m>`, `ollama:<m>`, `openai-compat:<m>`, plugins) -> `Model`.

Every provider, built-in or not, is a factory `factory(model_name, **opts) -> Model` under a
prefix. Plugins register through the entry point group `iesm_agent.providers`
(name = prefix, object = factory) or at run time with `register_provider`. Factories receive
`base_url`, `api_key_env`, `timeout`, `max_retries`, `concurrency` and any extra options
(`context_window`, tokens, `deadline`, seconds per call, and `dialect`, the structured-output
dialect instead of a negotiated one, for the HTTP providers); built-ins win over plugins of the
same name.
`ollama:` speaks Ollama's native API (`ollama.py`), `llamacpp:<file.gguf>` runs llama.cpp in
this process (`llamacpp.py`).
"""

from __future__ import annotations

import os
from importlib.metadata import entry_points
from pathlib import Path
from typing import Any, Callable

from ..errors import IesmError
from .base import Model

Factory = Callable[..., Model]

ENTRY_POINT_GROUP = "iesm_agent.providers"
OPENAI_URL = "https://api.openai.com/v1"
_TRANSPORT = ("base_url", "api_key_env", "timeout", "max_retries", "concurrency", "context_window", "deadline",
              "dialect")


def _offline(model_name: str, **opts: Any) -> Model:
    for key in _TRANSPORT:
        opts.pop(key, None)
    if model_name:
        raise IesmError(f"the offline model takes no model name, got {model_name!r}", "offline")
    try:  # deferred: loads lexicons (and maybe embeddings)
        from .offline import OfflineModel
    except ImportError as exc:
        raise IesmError(f"the offline model is unavailable: {exc}", "offline") from exc
    try:
        return OfflineModel(**opts)
    except TypeError as exc:
        raise IesmError(f"bad option for the offline model: {exc}", "offline") from exc


def _api_key(source: str, env: str | None, defaults: tuple[str, ...] = ()) -> tuple[str | None, str | None]:
    """(key, hint): from `env` if given (it must be set), else the first set of `defaults`."""
    if env:
        if not os.environ.get(env):
            raise IesmError(f"environment variable {env} is not set", source, "api_key_env")
        return os.environ[env], f"${env}"
    for name in defaults:
        if os.environ.get(name):
            return os.environ[name], f"${name}"
    return None, None


def _http(provider: str, model_name: str, base_url: str, key: tuple[str | None, str | None],
          opts: dict[str, Any]) -> Model:
    # deferred: httpx import costs ~50 ms
    if provider == "ollama":
        from .ollama import OllamaModel as cls
    else:
        from .openai_compat import OpenAICompatModel as cls

    opts.pop("api_key_env", None)
    opts.pop("base_url", None)
    try:
        return cls(model_name, base_url=base_url, api_key=key[0], provider=provider,
                   key_hint=key[1], **opts)
    except TypeError as exc:
        raise IesmError(f"bad option: {exc}", f"{provider}:{model_name}") from exc


def _require_name(provider: str, model_name: str) -> None:
    if not model_name:
        raise IesmError(f"give a model name, e.g. {provider}:<model>", provider)


def _openai(model_name: str, **opts: Any) -> Model:
    _require_name("openai", model_name)
    opts.setdefault("vision", True)
    if opts.get("base_url"):  # an OpenAI-compatible server: a key only if one is set
        return _openai_compat(model_name, **opts)
    source = f"openai:{model_name}"
    key = _api_key(source, opts.get("api_key_env"), ("OPENAI_API_KEY",))
    if key[0] is None:
        raise IesmError("set the environment variable OPENAI_API_KEY to an API key", source, "api_key")
    opts.setdefault("probe_window", False)  # OpenAI names the window in its refusals
    return _http("openai", model_name, OPENAI_URL, key, opts)


def _ollama(model_name: str, **opts: Any) -> Model:
    _require_name("ollama", model_name)
    key = _api_key(f"ollama:{model_name}", opts.get("api_key_env"))
    return _http("ollama", model_name, opts.get("base_url") or "http://localhost:11434", key, opts)


def _openai_compat(model_name: str, **opts: Any) -> Model:
    _require_name("openai-compat", model_name)
    source = f"openai-compat:{model_name}"
    base_url = opts.get("base_url") or os.environ.get("IESM_BASE_URL")
    if not base_url:
        raise IesmError("needs base_url= (or the environment variable IESM_BASE_URL)", source, "base_url")
    key = _api_key(source, opts.get("api_key_env"), ("IESM_API_KEY", "OPENAI_API_KEY"))
    return _http("openai-compat", model_name, base_url, key, opts)


def _llamacpp(model_name: str, **opts: Any) -> Model:
    if not model_name:
        raise IesmError("give a GGUF file, e.g. llamacpp:models/gemma.gguf", "llamacpp")
    window = opts.pop("context_window", None)
    for key in _TRANSPORT:
        opts.pop(key, None)
    from .llamacpp import LlamaCppModel  # llama_cpp itself is imported on the first call

    try:
        return LlamaCppModel(model_name, context_window=window, **opts)
    except TypeError as exc:
        raise IesmError(f"bad option: {exc}", f"llamacpp:{model_name}") from exc


_BUILTINS: dict[str, Factory] = {"offline": _offline, "openai": _openai, "ollama": _ollama,
                                 "openai-compat": _openai_compat, "llamacpp": _llamacpp}
_REGISTERED: dict[str, Factory] = {}


def register_provider(prefix: str, factory: Factory) -> None:
    """Add (or replace) a provider at run time; built-in prefixes cannot be replaced."""
    if prefix in _BUILTINS:
        raise IesmError(f"{prefix!r} is a built-in provider", "register_provider")
    _REGISTERED[prefix] = factory


def providers() -> dict[str, Factory]:
    """All known prefixes -> factories: built-ins, run-time registrations, entry points."""
    found: dict[str, Factory] = {}
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        found.setdefault(ep.name, _EntryPointFactory(ep))
    return {**found, **_REGISTERED, **_BUILTINS}


class _EntryPointFactory:
    """Loads the entry point only when its provider is asked for."""

    def __init__(self, ep: Any):
        self.ep = ep

    def __call__(self, model_name: str, **opts: Any) -> Model:
        try:
            factory = self.ep.load()
        except Exception as exc:  # a broken plugin must not look like our bug
            raise IesmError(f"cannot load provider plugin {self.ep.value!r}: {exc}",
                            f"entry point {ENTRY_POINT_GROUP}:{self.ep.name}") from exc
        return factory(model_name, **opts)


def _default_timeout() -> float:
    """`$IESM_TIMEOUT` (seconds) when set, else 60."""
    value = os.environ.get("IESM_TIMEOUT")
    if not value:
        return 60.0
    try:
        return float(value)
    except ValueError:
        raise IesmError(f"must be a number of seconds, got {value!r}", "IESM_TIMEOUT") from None


def get_model(spec: str | Model, *, base_url: str | None = None, api_key_env: str | None = None,
              cache: bool | str | Path | None = None, timeout: float | None = None, max_retries: int = 4,
              concurrency: int = 8, **opts: Any) -> Model:
    """The model named by `spec` (`prefix` or `prefix:model`; a `Model` passes through).

    `timeout` in seconds per request (default `$IESM_TIMEOUT`, else 60: a local server that
    answers one request at a time needs more); `cache`: None/False none, True the default directory, a path that
    directory (wraps the model in `CachedModel`; not for models that are not `cacheable`). Unknown prefixes raise `IesmError` listing
    the known ones.
    """
    if isinstance(spec, Model):
        model = spec
    else:
        if not isinstance(spec, str) or not spec.strip():
            raise IesmError(f"model spec must be a non-empty string, got {spec!r}", "model")
        prefix, _, name = spec.strip().partition(":")
        factory = _BUILTINS.get(prefix) or _REGISTERED.get(prefix)
        if factory is None:  # only now scan installed distributions (tens of ms)
            table = providers()
            factory = table.get(prefix)
            if factory is None:
                raise IesmError(f"unknown provider {prefix!r}; known: {', '.join(sorted(table))}",
                                "model", spec)
        model = factory(name, base_url=base_url, api_key_env=api_key_env,
                        timeout=timeout if timeout is not None else _default_timeout(),
                        max_retries=max_retries, concurrency=concurrency, **opts)
        if not isinstance(model, Model):
            raise IesmError(f"provider {prefix!r} returned {type(model).__name__}, not a Model",
                            "model", spec)
    if cache is None or cache is False or not model.cacheable:
        return model
    from .cache import CachedModel  # diskcache only when a cache is asked for

    if isinstance(model, CachedModel):
        return model
    return CachedModel(model, None if cache is True else cache)
