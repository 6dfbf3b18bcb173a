"""Triangle's console statistics for the command line.

The computation and formatting live in the engine (``instrument.statistics``),
which prints the same text for the library's ``V`` switch; this module keeps
the names the command line and its users import from ``ruppert_io.stats``.
"""

from instrument.statistics import (  # noqa: F401  (re-exported)
    COS_SQUARE_TABLE,
    RATIO_TABLE,
    WORK_LABELS,
    MeshCounts,
    QualityStats,
    format_algorithmic,
    format_quality,
    format_work,
    mesh_counts,
    phase_lines,
    quality_statistics,
    statistics_block,
    triangle_rows,
)

__all__ = [
    "MeshCounts",
    "QualityStats",
    "mesh_counts",
    "phase_lines",
    "statistics_block",
    "quality_statistics",
    "format_quality",
    "format_algorithmic",
    "format_work",
    "triangle_rows",
    "WORK_LABELS",
]
