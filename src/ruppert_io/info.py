"""Metadata gathered while reading a file set, for the command line."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path


@dataclass
class Info:
    """What a read learned besides the arrays.

    Attributes:
        first_index: the numbering base of the file set (0 or 1), decided by the
            number of the first vertex; indices in the returned dict are 0-based.
        vertex_markers: the boundary-marker count declared in the vertex header
            (Triangle treats any nonzero value as "one marker column").
        segment_markers: the marker count declared in the .poly segment header.
        warnings: Triangle's warnings, verbatim (e.g. ``"Warning:  Invalid first
            endpoint of segment 3 in A.poly."``); the offending items were skipped.
        files: every file read, in order.
        vertices_from: the file that supplied the vertices (a .poly, or a .node).
    """

    first_index: int = 1
    vertex_markers: int = 0
    segment_markers: int = 0
    warnings: list[str] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)
    vertices_from: Path | None = None
