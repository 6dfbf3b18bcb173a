"""The engine and the ``ruppert`` command never load the study's dependencies."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import triangle

TRIANGLE_DATA = Path(triangle.__file__).parent / "data"  # Triangle's samples (not shipped here)
HEAVY = ("dask", "distributed", "pyarrow", "pebble", "instrument.study")

PROBE = f"""
import sys
import instrument
from ruppert_io.cli import main
code = main(["-pq30", "A.poly"])
loaded = sorted(m for m in sys.modules if m.split(".")[0] in {HEAVY!r} or m.startswith("instrument.study"))
print(code, loaded)
"""


def test_importing_instrument_and_running_ruppert_loads_no_study_dependency(tmp_path):
    shutil.copy(TRIANGLE_DATA / "A.poly", tmp_path / "A.poly")
    proc = subprocess.run([sys.executable, "-c", PROBE], cwd=tmp_path, capture_output=True, text=True, timeout=300,
                          check=False)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip().splitlines()[-1] == "0 []"
    assert (tmp_path / "A.1.ele").is_file()


def test_the_engine_runners_need_no_dask():
    """``instrument.study.engines`` and the benchmark load without the sweep's dependencies."""
    probe = ("import sys; import instrument.study.engines, instrument.study.compare; "
             "import instrument.study.bench.main, instrument.study.bench.timing, instrument.study.bench.cold; "
             f"print(sorted(m for m in sys.modules if m.split('.')[0] in {HEAVY[:3]!r}))")
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300, check=False)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"
