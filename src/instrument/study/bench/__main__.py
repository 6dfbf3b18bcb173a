"""``python -m instrument.study.bench``."""

import sys

from .main import main

if __name__ == "__main__":  # also imported by the isolated processes (spawn), which must not run it
    sys.exit(main())
