"""JSON schemas for tool functions, derived from their signature and docstring.

The description is the docstring's first line; a parameter's description comes from a
Google-style `Args:` section (`name: text`) when present. Type hints map to JSON types
(int -> integer, float -> number, str -> string, bool -> boolean, list/tuple -> array,
dict -> object, Optional[X] -> X and not required, Literal -> enum).
"""

from __future__ import annotations

import inspect
import re
import types
import typing
from typing import Any, Callable, Literal, Union

_SIMPLE = {int: "integer", float: "number", str: "string", bool: "boolean", dict: "object", list: "array"}
_ARG_LINE = re.compile(r"^\s*(\w+)\s*(?:\([^)]*\))?\s*:\s*(.+)$")


def json_type(tp: Any) -> dict[str, Any]:
    """JSON schema fragment for a Python type hint ({} when it has no JSON equivalent)."""
    origin, args = typing.get_origin(tp), typing.get_args(tp)
    if origin in (Union, types.UnionType):
        options = [json_type(a) for a in args if a is not type(None)]
        return options[0] if len(options) == 1 else {"anyOf": options}
    if origin is Literal:
        return {**json_type(type(args[0])), "enum": list(args)}
    if origin in (list, tuple, set, frozenset) or tp in (list, tuple):
        item = json_type(args[0]) if args else {}
        return {"type": "array", **({"items": item} if item else {})}
    if origin is dict:
        return {"type": "object"}
    return {"type": _SIMPLE[tp]} if tp in _SIMPLE else {}


def _arg_docs(doc: str) -> dict[str, str]:
    """Parameter descriptions from an indented `Args:` section (ends at an unindented line)."""
    out: dict[str, str] = {}
    in_args, last = False, None
    for line in doc.splitlines():
        if line.strip() in ("Args:", "Arguments:", "Parameters:"):
            in_args = True
        elif in_args and line.strip() and not line.startswith(" "):
            in_args = False
        elif in_args and (match := _ARG_LINE.match(line)):
            last = match.group(1)
            out[last] = match.group(2).strip()
        elif in_args and last and line.strip():
            out[last] += " " + line.strip()
    return out


def function_schema(fn: Callable[..., Any], name: str | None = None) -> dict[str, Any]:
    """{"name", "description", "parameters"} for `fn` (a bound method drops `self`).
    `parameters` is a JSON schema object; parameters without a default are required."""
    doc = inspect.getdoc(fn) or ""
    hints = typing.get_type_hints(fn)
    arg_docs = _arg_docs(doc)
    props, required = {}, []
    for pname, param in inspect.signature(fn).parameters.items():
        if param.kind in (param.VAR_POSITIONAL, param.VAR_KEYWORD):
            continue
        schema = json_type(hints.get(pname, Any))
        if pname in arg_docs:
            schema["description"] = arg_docs[pname]
        if param.default is param.empty:
            required.append(pname)
        elif param.default is not None:
            schema["default"] = param.default
        props[pname] = schema
    parameters: dict[str, Any] = {"type": "object", "properties": props}
    if required:
        parameters["required"] = required
    return {"name": name or fn.__name__, "description": doc.split("\n", 1)[0].strip(), "parameters": parameters}
