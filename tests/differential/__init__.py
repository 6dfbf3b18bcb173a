"""Differential testing of ruppert against Triangle (the `triangle` package).

Generated inputs (``families``) crossed with switch strings drawn from
Triangle's grammar run through Triangle in a subprocess and through ours
(``runners``); ``oracles`` say what must agree.  ``campaign`` runs a large
number of cases outside pytest and writes every failure, shrunk, as a JSON
case (``cases``); ``regressions/`` keeps those, replayed by the tests.
"""
