#!/usr/bin/env python
"""``python -m instrument.study.quadratic``, writing to the repository's docs/quadratic by default."""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from instrument.study.quadratic.cli import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main(default_out=ROOT / "docs" / "quadratic"))
