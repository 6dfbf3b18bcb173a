"""The command's one failure type: every other module of the command raises it
for a failure the user should see as one ``Error:`` line (``main`` prints it)."""

from __future__ import annotations


class CliError(Exception):
    """A failure reported as one ``Error:`` line and exit status 1."""
