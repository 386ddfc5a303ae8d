"""Errors that the CLI turns into one line on stderr and exit status 2."""

from __future__ import annotations

from pathlib import Path


class IesmError(Exception):
    """A user-facing error: bad input, bad configuration, unusable file.

    `source` names the file (or endpoint) at fault; `where` narrows it down
    (a field, a line number, a byte offset).
    """

    def __init__(self, message: str, source: str | Path | None = None, where: str | None = None):
        self.message = message
        self.source = str(source) if source is not None else None
        self.where = where
        super().__init__(self.__str__())

    def __str__(self) -> str:
        head = self.source or ""
        if self.where:
            head = f"{head}:{self.where}" if head else self.where
        return f"{head}: {self.message}" if head else self.message


class MapFormatError(IesmError):
    """A map file or an importer input is malformed."""


class ProviderError(IesmError):
    """A model endpoint failed. `retryable` tells the client whether to try again."""

    def __init__(self, message: str, source: str | None = None, *, retryable: bool = False,
                 status: int | None = None, retry_after: float | None = None):
        super().__init__(message, source)
        self.retryable = retryable
        self.status = status
        self.retry_after = retry_after
