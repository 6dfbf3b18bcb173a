"""A copy of the engine built with bounds checking, for tests that run
meshing paths under it.

The ordinary build compiles kernels without bounds checks (an index out of
range would corrupt memory silently).  ``checked_tree()`` builds the same
sources with ``RUPPERT_BOUNDSCHECK=1`` (see setup.py) into
``build/checked/<hash of the sources>/`` beside the checkout, once per
change of the sources, and returns the directory to put on ``PYTHONPATH``.
In that build an out-of-range index raises ``IndexError`` inside the
kernel, which Python reports as an exception it had to ignore (the
kernels cannot propagate exceptions); ``run_checked.py`` turns every such
report into a failure.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def _sources() -> list[Path]:
    files = [REPO / "setup.py", REPO / "pyproject.toml"]
    files += sorted(p for p in (REPO / "src").rglob("*") if p.suffix in (".py", ".pxd") and "__pycache__" not in p.parts)
    return files


def _digest(files: list[Path]) -> str:
    h = hashlib.sha256()
    for p in files:
        h.update(str(p.relative_to(REPO)).encode())
        h.update(p.read_bytes())
    return h.hexdigest()[:16]


def checked_tree(timeout: float = 900) -> Path:
    """The ``src`` directory of a bounds-checked build of the current sources."""
    files = _sources()
    root = REPO / "build" / "checked" / _digest(files)
    done = root / ".built"
    if done.exists():
        return root / "src"
    if root.exists():
        shutil.rmtree(root)
    for p in files:
        target = root / p.relative_to(REPO)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(p, target)
    env = dict(os.environ, RUPPERT_BOUNDSCHECK="1")
    env.pop("RUPPERT_PURE_PYTHON", None)
    proc = subprocess.run(
        [sys.executable, "setup.py", "build_ext", "--inplace", "-q", "-j", str(os.cpu_count() or 1)],
        cwd=root, env=env, capture_output=True, text=True, timeout=timeout,
    )
    if proc.returncode != 0:
        raise RuntimeError(f"the bounds-checked build failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    done.write_text("ok\n")
    return root / "src"
