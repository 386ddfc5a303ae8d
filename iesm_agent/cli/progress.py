"""The progress bar every long CLI command shows on stderr."""

from __future__ import annotations

import os


def progress_bar(label: str):
    """A rich progress bar on stderr labelled `label`, disabled when stderr is not a terminal or
    under CI (`CI` set)."""
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    console = Console(stderr=True)
    return Progress(TextColumn(label), BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                    console=console, transient=True,
                    disable=not console.is_terminal or bool(os.environ.get("CI")))
