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


_COMMAND_MODULES = ("store_cmds", "ask_cmd", "eval_cmds", "serve_cmds", "sim_cmds", "mapping_cmds",
                    "nav_cmds",
                    "caption_cmds")


def _register_commands() -> None:
    import importlib

    for name in _COMMAND_MODULES:
        try:
            module = importlib.import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"{__name__}.{name}":
                continue  # command group not built yet
            raise
        module.register(app)


_register_commands()


def run(argv: list[str] | None = None) -> int:
    """Run one `iesm` command line in this process and return its exit status: user errors
    become one line on stderr and status 2."""
    try:
        status = app(args=argv, standalone_mode=False)  # a command's typer.Exit code, or None
    except IesmError as exc:
        print(f"iesm: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("iesm: interrupted", file=sys.stderr)
        return 130
    except typer.Exit as exc:
        return exc.exit_code
    except Exception as exc:  # click usage errors and aborts
        import click

        if isinstance(exc, click.exceptions.ClickException):
            exc.show()
            return 2
        if isinstance(exc, click.exceptions.Abort):
            return 130
        raise
    return status if isinstance(status, int) else 0


def main() -> None:
    """Console entry point (`iesm`)."""
    sys.exit(run())
