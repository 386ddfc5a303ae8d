"""Goal retrieval for assistants: the tools (`tools.py`, no MCP dependency) and the MCP server
over them (`app.py`, needs the `mcp` extra)."""

from .tools import MapService, format_specs, tool_specs

__all__ = ["MapService", "tool_specs", "format_specs"]
