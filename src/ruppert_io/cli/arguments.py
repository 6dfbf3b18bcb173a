"""Splitting the command line into Triangle's switches, the file name and the long options.

Triangle's switch groups (``-pq30a0.1``, ``-p -q30``) may come before or after
the file name and are left as text for ``instrument.switches.parse``; the long
options (``--strategy fifo`` or ``--strategy=fifo``) go to argparse, whose
errors become ``CliError`` instead of argparse's usage text and exit status 2.
"""

from __future__ import annotations

import argparse
import dataclasses

from .errors import CliError


_LONG_WITH_VALUE = ("--strategy", "--steiner", "--seed", "--work-json", "--trace", "--format", "--max-vertices", "--threads")


class _ArgumentParser(argparse.ArgumentParser):
    def error(self, message: str):  # argparse would print usage and exit 2
        raise CliError(message)


def _long_parser() -> argparse.ArgumentParser:
    p = _ArgumentParser(prog="ruppert", add_help=False, allow_abbrev=False)
    p.add_argument("--strategy", default="triangle")
    p.add_argument("--steiner", default="offcenter", choices=("offcenter", "circumcenter"))
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--work-json", dest="work_json", default=None)
    p.add_argument("--trace", default=None)
    p.add_argument("--format", dest="formats", action="append", default=[])
    p.add_argument("--progress", action="store_true")
    p.add_argument("--max-vertices", dest="max_vertices", type=_positive_int, default=None)
    p.add_argument("--threads", type=_positive_int, default=None)
    p.add_argument("--help", action="store_true")
    p.add_argument("--version", action="store_true")
    return p


def _positive_int(text: str) -> int:
    try:
        value = int(text.replace("_", "").replace(",", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be positive, not {value}")
    return value


@dataclasses.dataclass
class Command:
    """The command line, split (see ``split_argv``)."""

    switches: str  # the switch text, one leading dash removed per group
    file: str | None
    long: argparse.Namespace
    argv: list[str]


def split_argv(argv: list[str]) -> Command:
    """Switch groups, the file name (the last one given) and the parsed long
    options; everything after ``--`` is a file name."""
    groups, files, long_tokens = [], [], []
    it = iter(argv)
    only_files = False
    for arg in it:
        if only_files:
            files.append(arg)
        elif arg == "--":
            only_files = True
        elif arg.startswith("--"):
            name = arg.split("=", 1)[0]
            if name in _LONG_WITH_VALUE and "=" not in arg:
                value = next(it, None)
                if value is None:
                    raise CliError(f"argument {name}: expected one argument")
                arg = f"{name}={value}"
            long_tokens.append(arg)
        elif arg.startswith("-"):
            groups.append(arg[1:])
        else:
            files.append(arg)
    long = _long_parser().parse_args(long_tokens)
    # A space between groups keeps "-q -30" from reading as "-q30", as in Triangle.
    return Command(" ".join(groups), files[-1] if files else None, long, argv)
