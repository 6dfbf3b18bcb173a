#!/usr/bin/env python
"""``python -m instrument.study.compare``, with the shared corpus beside the repository as the default corpus."""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from instrument.study.compare import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main(default_corpus=ROOT.parent / "shared" / "corpus"))
