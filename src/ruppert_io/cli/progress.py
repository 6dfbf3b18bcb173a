"""The progress display of a long run, on a terminal only.

The engine calls the display whenever its kernel hands back control; the
display shows itself only once a run has taken ``after`` seconds (the
command's ``PROGRESS_AFTER``; at once with ``--progress``), never with ``-Q``
or when stderr is not a terminal, so short runs and redirected output look
exactly like Triangle's.
"""

from __future__ import annotations

import time


def is_terminal(stream) -> bool:
    """Whether ``stream`` is a terminal (False for streams that cannot say)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class Progress:
    """The progress display on a terminal (stderr), with rich: it appears
    once the run has taken ``after`` seconds (at once with ``--progress``,
    ``eager``) and shows the refinement's vertices against the limit.
    The engine calls it whenever its kernel hands back control."""

    def __init__(self, *, enabled: bool, eager: bool, after: float):
        self.enabled = enabled
        self.eager = eager
        self.after = after
        self.start = time.perf_counter()
        self.status = None

    def __enter__(self):
        if self.enabled and self.eager:
            self._show("Meshing...")
        return self

    def __exit__(self, *exc) -> None:
        if self.status is not None:
            self.status.stop()
            self.status = None

    def __call__(self, vertices: int, limit: int) -> None:
        if not self.enabled:
            return
        text = f"Refining: {vertices:,} vertices (limit {limit:,})"
        if self.status is not None:
            self.status.update(text)
        elif time.perf_counter() - self.start >= self.after:
            self._show(text)

    def _show(self, text: str) -> None:
        from rich.console import Console  # only for runs that show it (rich comes with meshio)

        self.status = Console(stderr=True).status(text)
        self.status.start()
