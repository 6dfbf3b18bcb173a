#!/usr/bin/env python
"""``python -m instrument.study.bench``, under the name the README's commands use.

The benchmark lives in the package (``instrument/study/bench/``); this shell
only runs it: ``python scripts/bench.py ARGS`` is ``python -m instrument.study.bench ARGS``.
"""

import sys

from instrument.study.bench.main import main

if __name__ == "__main__":
    sys.exit(main())
