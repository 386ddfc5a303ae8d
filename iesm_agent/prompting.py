"""Jinja prompt templates -> chat messages.

A template defines `{% block system %}` and `{% block user %}`; each block becomes one
message (an empty block is left out). Templates are looked up by file name in the user
directories first, then in the shipped `prompts/`, so a user folder overrides any
template by name. Data is fenced with the `fence` filter (JSON, with <, >, & escaped;
`fence_lines` gives one such line per item), so untrusted captions cannot close a fence or
inject instructions as markup. Templates render in Jinja's sandbox: attribute access to
internals (`__globals__`, `__subclasses__`, ...) is refused, so a template cannot run code.
"""

from __future__ import annotations

import functools
import hashlib
import json
from pathlib import Path
from typing import Any, Iterable

from . import contract
from .errors import IesmError
from .providers.base import Message
from .resources import resource_dir


def fence(value: Any) -> str:
    """Compact JSON of `value` with <, >, & and ' escaped (safe inside tag fences)."""
    if isinstance(value, Fenced):
        return value.fenced
    if type(value) is str:
        return _fenced_text(value)
    return _fenced_json(value)


def _fenced_json(value: Any) -> str:
    text = json.dumps(value, ensure_ascii=False, separators=(", ", ": "))
    return (text.replace("&", "\\u0026").replace("<", "\\u003c")
            .replace(">", "\\u003e").replace("'", "\\u0027"))


@functools.lru_cache(maxsize=1024)
def _fenced_text(text: str) -> str:
    """`fence` of a string, memoised: the prompts of one query fence the same query, and every
    gate prompt the same expert names and descriptions (about 20 strings a query, 2-4 us each)."""
    return _fenced_json(text)


def fence_lines(values: Iterable[Any]) -> str:
    """One `fence`d line per value (e.g. the candidate list inside `<candidates>`)."""
    if isinstance(values, FencedList):
        return values.fenced_lines
    return "\n".join(map(fence, values))


class Fenced(dict):
    """A dict that carries its `fence` text, computed once: for data rendered into many prompts
    (candidate views). Do not mutate it after construction."""

    def __init__(self, data: dict):
        super().__init__(data)
        self.fenced = fence(data)


class FencedList(list):
    """A list of `Fenced` items carrying its `fence_lines` text, computed once (the candidate
    block shared by the expert prompts of one query). Do not mutate it after construction."""

    def __init__(self, items: Iterable[Fenced]):
        super().__init__(items)
        self.fenced_lines = "\n".join(item.fenced for item in self)


@functools.lru_cache(maxsize=1)
def _sandbox() -> type:
    """Jinja's `SandboxedEnvironment` with each template's globals as one dict (the library's,
    overlaid by the template's own) instead of Jinja's `ChainMap` over the two: a render copies
    them into a context for the template and one for each `{% include %}`, and a `ChainMap` is
    iterated in Python (about half of a render's time went there). The library sets its globals
    before it loads a template and never changes them, so a snapshot is the same map."""
    from jinja2.sandbox import SandboxedEnvironment

    class Sandbox(SandboxedEnvironment):
        def make_globals(self, d: dict[str, Any] | None) -> dict[str, Any]:
            return {**self.globals, **(d or {})}

    return Sandbox


class PromptLibrary:
    """Renders named templates from `dirs` (searched first) and the shipped `prompts/`."""

    def __init__(self, dirs: Iterable[str | Path] = ()):
        import jinja2

        self.dirs = [Path(d) for d in dirs] + [resource_dir("prompts")]
        self._exists: dict[str, bool] = {}
        for d in self.dirs[:-1]:
            if not d.is_dir():
                raise IesmError("prompt directory does not exist", d)
        # sandboxed: a prompt directory is shared like code, but a template must not run code
        # (`{{ cycler.__init__.__globals__.os.popen(...) }}` is a SecurityError)
        self._env = _sandbox()(
            loader=jinja2.FileSystemLoader([str(d) for d in self.dirs]),
            undefined=jinja2.StrictUndefined,
            trim_blocks=True,
            lstrip_blocks=True,
            keep_trailing_newline=False,
            autoescape=False,
            # a template is read once per library, like its hash in the trace (`source_hash`,
            # memoised per retriever) and `has`: no file stat per render
            auto_reload=False,
        )
        self._env.filters["fence"] = fence
        self._env.filters["fence_lines"] = fence_lines
        self._env.globals.update(task_line=contract.task_line, reply_format=contract.reply_format)

    def has(self, name: str) -> bool:
        """True when a template `name` exists in the user directories or the shipped prompts
        (looked up once per library)."""
        found = self._exists.get(name)
        if found is None:
            found = self._exists[name] = any((d / name).is_file() for d in self.dirs)
        return found

    def template_for(self, expert: str, default: str) -> str:
        """The template an expert renders: `expert_<name>.j2` when one exists (a prompt experiment
        for that expert alone), else its spec's `default`."""
        own = f"expert_{expert}.j2"
        return own if self.has(own) else default

    def source_hash(self, name: str) -> str:
        """sha256 (hex, 12 chars) of the template source that `name` resolves to."""
        source, _, _ = self._env.loader.get_source(self._env, name)
        return hashlib.sha256(source.encode()).hexdigest()[:12]

    def render(self, name: str, **variables: Any) -> list[Message]:
        """Render template `name` into [system, user] messages."""
        import jinja2

        try:
            template = self._env.get_template(name)
            context = template.new_context(variables)
            messages = []
            for role in ("system", "user"):
                block = template.blocks.get(role)
                if block is None:
                    continue
                text = "".join(block(context)).strip()
                if text:
                    messages.append(Message(role=role, content=text))
        except jinja2.TemplateNotFound as exc:
            raise IesmError(f"prompt template {name!r} not found in {[str(d) for d in self.dirs]}") from exc
        except jinja2.TemplateError as exc:
            raise IesmError(f"cannot render prompt template: {' '.join(str(exc).split())}", name) from None
        if not messages:
            raise IesmError("template renders no system or user block", name)
        return messages
