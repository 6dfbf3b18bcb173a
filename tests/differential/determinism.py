"""Hypothesis draws the same cases whatever else the session imported.

Hypothesis (6.131 on) now and then draws a number it found in the source of
a local, non-test module loaded so far (its "local constants"), instead of a
random one.  Which modules are loaded depends on what pytest collected:
collecting ``tests/study`` imports ``instrument.study`` (plain Python, full
of constants), and from the 11th of the 30 fixed, derandomized cases on the
generated test drew other cases in a full-suite run than when
``tests/differential`` ran alone (a case that failed only in full-suite runs
was one of them).  ``fixed_constants`` empties that pool while cases are
drawn, so a seed names the same cases in the suite, alone and in the
campaign.  It patches a private function of Hypothesis: if that is gone, the
draws are as Hypothesis makes them (``test_draws_ignore_loaded_modules``
notices).
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator


@contextlib.contextmanager
def fixed_constants() -> Iterator[bool]:
    """While active, Hypothesis's local-constant pool is empty; yields
    whether the pool could be fixed."""
    try:
        from hypothesis.internal.conjecture import providers
        from hypothesis.internal.constants_ast import Constants
    except ImportError:  # a Hypothesis without local constants
        yield False
        return
    get = getattr(providers, "_get_local_constants", None)
    cache = getattr(providers, "CONSTANTS_CACHE", None)
    if get is None or cache is None:
        yield False
        return
    empty = Constants()
    providers._get_local_constants = lambda: empty
    cache.cache.clear()  # permitted constants computed from the pool so far
    try:
        yield True
    finally:
        providers._get_local_constants = get
        cache.cache.clear()
