"""``python -m ruppert_io.cli``: the ``ruppert`` command without its script."""

from . import main

raise SystemExit(main())
