"""The ``ruppert`` command line: Triangle 1.6's interface, plus a few long options.

    ruppert [-switches] input_file[.node|.poly|.ele|.area] [--long-options]
    ruppert [-switches] mesh.vtu|mesh.msh|mesh.mesh|... [--long-options]

Triangle-style switch groups (``-pq30a0.1``, ``-p -q30``, before or after the file
name) are parsed with ``instrument.switches.parse``; the long options with argparse.
``main`` is the only place that turns exceptions into exit statuses: every
failure is one ``Error:`` line on stderr and exit status 1 (130 when interrupted).

Modules
-------
``texts``      the usage line, ``-h``'s text, ``--version``;
``arguments``  argv split into switches, file name and long options;
``command``    one run: read, triangulate, write Triangle's files, report;
``outputs``    which of Triangle's files a run writes, and their mesh;
``meshio_input``  the input from a meshio file (mesh.vtu, outline.msh, ...);
``extras``     the long options' files (meshio formats, --work-json, --trace);
``verdict``    -C's report of the exact checker;
``progress``   the progress display on a terminal;
``errors``     ``CliError``, the failure reported as one ``Error:`` line.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Sequence

from .command import engine_switches, run
from .errors import CliError
from .extras import TRACE_HEADER
from .texts import LONG_HELP, SHORT_HELP, USAGE, version
from .verdict import CHECK_TEXT

__all__ = [
    "CHECK_TEXT",
    "LONG_HELP",
    "SHORT_HELP",
    "TRACE_HEADER",
    "USAGE",
    "PROGRESS_AFTER",
    "CliError",
    "console",
    "engine_switches",
    "main",
    "version",
]

#: A run shows its progress on a terminal once it has taken this long
#: (seconds).  ``main`` reads it at every call, so a test may change it here.
PROGRESS_AFTER = 1.0


def console() -> int:
    """The ``ruppert`` command: ``main`` in a process of its own."""
    return main()


def main(argv: Sequence[str] | None = None) -> int:
    """Run ruppert with ``argv`` (default: ``sys.argv[1:]``); return the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        return run(argv, sys.stdout, progress_after=PROGRESS_AFTER)
    except CliError as exc:
        _error(str(exc))
        return 1
    except KeyboardInterrupt:
        print("Error: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `ruppert -V x | head`: stop quietly
        try:
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except (OSError, ValueError, AttributeError):
            pass
        return 1
    except MemoryError:
        _error("Out of memory.")
        return 1
    except Exception as exc:  # a bug: still one line, never a traceback
        if os.environ.get("RUPPERT_DEBUG"):
            raise
        _error(f"internal error ({type(exc).__name__}): {exc}")
        return 1


def _error(message: str) -> None:
    message = " ".join(str(message).split()) or "unknown error"
    print(f"Error:  {message}", file=sys.stderr)
