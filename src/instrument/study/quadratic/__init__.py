"""Barbič and Miller's quadratic example I(n), measured: ``python -m instrument.study.quadratic``.

Modules, one idea each: ``replay_engine`` (Theorem 3's script as a sweep
engine), ``runs`` (the grid of runs, through ``instrument.study.sweep``, and
the rows it gives back), ``fit`` (log-log slopes, the least-work strategy),
``tables`` (Markdown tables), ``plots`` (the figures), ``report`` (results.md,
README-section.md, CSV and JSON), ``cli`` (the command line).
"""
