"""Differential tests against Triangle: generated cases and the regression cases.

The generated test runs a small, fixed (derandomized) sample by default;
``RUPPERT_DIFF_EXAMPLES=20000`` runs that many random cases instead
(``RUPPERT_DIFF_SEED`` picks the seed).  A failure that a known, open
defect explains (``known.DEFECTS``) does not fail it; any other failure
does, after Hypothesis has shrunk it, and the shrunk case is written as
JSON to ``RUPPERT_DIFF_OUT`` (default: pytest's temporary directory) so it
can be kept under ``regressions/``.

Every file in ``regressions/`` is replayed with the same oracles; one that
names an open defect is ``xfail(strict=True)``: it must still fail, so a fix
shows up as an unexpected pass and its file is then updated.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, seed, settings

from . import known
from .cases import read_case, write_case
from .determinism import fixed_constants
from .families import cases
from .harness import run_case

DEFAULT_EXAMPLES = 30
EXAMPLES = int(os.environ.get("RUPPERT_DIFF_EXAMPLES", DEFAULT_EXAMPLES))
SEED = int(os.environ.get("RUPPERT_DIFF_SEED", "0"))
REGRESSIONS = sorted((Path(__file__).parent / "regressions").glob("*.json"))

_confirmed: dict = {}


def _out_dir(tmp_path_factory) -> Path:
    env = os.environ.get("RUPPERT_DIFF_OUT")
    return Path(env) if env else tmp_path_factory.getbasetemp() / "differential-failures"


@pytest.fixture
def same_draws():
    """The generated cases do not depend on what else the session imported."""
    with fixed_constants():
        yield


def _describe(run, failures) -> str:
    lines = [run.case.describe(), f"  Triangle: {run.triangle.summary()}", f"  ours:     {run.ours.summary()}"]
    lines += [f"  {f.signature}: {f.message[:800]}" for f in failures]
    return "\n".join(lines)


@settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=EXAMPLES == DEFAULT_EXAMPLES and not SEED,
    database=None,
    suppress_health_check=list(HealthCheck),
)
@seed(SEED)
@given(case=cases())
def test_generated_cases_agree_with_triangle(runners, tmp_path_factory, same_draws, case):
    run = run_case(runners, case, confirmed=_confirmed)
    if run is None:
        return  # Triangle made no mesh to refine
    open_failures = [f for f in run.verdict.failures if known.explaining(run.case, f, run.verdict.notes) is None]
    if open_failures:
        out = _out_dir(tmp_path_factory)
        path = out / f"{open_failures[0].signature.replace(':', '-')}.json"
        write_case(path, run.case, triangle=run.triangle.summary(), ours=run.ours.summary(),
                   failures=[f"{f.signature}: {f.message[:600]}" for f in open_failures])
        pytest.fail(_describe(run, open_failures) + f"\n  case written to {path}", pytrace=False)


def _regression_params():
    params = []
    for path in REGRESSIONS:
        case, meta = read_case(path)
        defect = known.BY_ID.get(meta.get("defect", ""))
        marks = [pytest.mark.xfail(strict=True, reason=defect.description)] if defect else []
        params.append(pytest.param(path, marks=marks, id=path.stem))
    return params


@pytest.mark.parametrize("path", _regression_params())
def test_regression_case(runners, path):
    case, meta = read_case(path)
    # a failure of a case that should pass is confirmed in a fresh process (a
    # worker corrupted by an earlier case cannot fake one); an open defect's
    # failure needs no confirmation (crashes are confirmed all the same)
    run = run_case(runners, case, confirmed={}, confirmations=0 if meta.get("defect") else 1)
    assert run is not None, "the case no longer makes an input"
    assert run.verdict.ok, _describe(run, run.verdict.failures)


def test_regressions_name_known_defects():
    """Every regression file names no defect (it passes) or a defect of ``known``."""
    for path in REGRESSIONS:
        _, meta = read_case(path)
        assert not meta.get("defect") or meta["defect"] in known.BY_ID, (path.name, meta.get("defect"))


def _draw(n: int) -> list[str]:
    drawn = []

    @settings(max_examples=n, deadline=None, derandomize=True, database=None, suppress_health_check=list(HealthCheck))
    @given(case=cases())
    def draw(case):
        drawn.append(f"{case.switches} {case.describe()} {np.asarray(case.input['vertices']).ravel()[:4].tolist()}")

    with fixed_constants() as fixed:
        assert fixed, "Hypothesis's local-constant pool could not be fixed (determinism.py)"
        draw()
    return drawn


def test_draws_ignore_loaded_modules(tmp_path, monkeypatch):
    """The cases a seed draws do not change when a local module full of
    numeric constants is imported (as collecting other tests does)."""
    before = _draw(40)
    # numbers like those of instrument.study, which collecting tests/study imports
    (tmp_path / "many_constants.py").write_text(
        "SCALES = (0.0, 0.5, 1.0, -1.0, 1.7, 1.9, 0.05, 0.1, 0.2, 0.25, 0.475, 0.6, 0.75, 1.5, 1e-300, 1e-09)\n"
        "SIZES = (100, 110, 130, 300, 400, 1000, 12345, 2654435761, 128, 512, 1024, 65536, 1000000)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    __import__("many_constants")
    assert _draw(40) == before
