"""The one exception type the file readers raise for bad file contents."""

from __future__ import annotations

import os


class FormatError(ValueError):
    """A Triangle-format file that cannot be read.

    Attributes:
        path: the file, as it was named when opened.
        line: 1-based line number (for an early end of file, the line after the last
            one), or None when no line applies.
        expected: what the reader was looking for, e.g. ``"the y coordinate of vertex 3"``.
        problem: what went wrong instead, when it is more than a missing field
            (e.g. ``"unexpected end of file"``), else None.
        found: the offending text or value, or None.
    """

    def __init__(
        self,
        path: str | os.PathLike[str],
        line: int | None,
        expected: str,
        *,
        problem: str | None = None,
        found: str | None = None,
    ) -> None:
        self.path = os.fspath(path)
        self.line = line
        self.expected = expected
        self.problem = problem
        self.found = found
        where = f"{self.path}, line {line}" if line is not None else self.path
        text = f"expected {expected}"
        if found is not None:
            text += f", found {found}"
        if problem is not None:
            text = f"{problem}; {text}"
        super().__init__(f"{where}: {text}")


class DimensionError(FormatError):
    """The file describes points in a dimension other than 2 (e.g. a TetGen file).

    A separate class so that the meshio plugin can let such files fall through to
    meshio's own TetGen reader.
    """
