"""Keep a failing case (from a campaign or a failed test) as a regression case.

    python -m tests.differential.promote OUT/size.json --name steiner-budget-star --defect steiner-budget

copies the case to ``regressions/NAME.json`` with the defect's id (an open
defect of ``known``: the replay is then an xfail(strict=True)), or without
one for a case that must pass.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import known

REGRESSIONS = Path(__file__).with_name("regressions")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", type=Path)
    ap.add_argument("--name", required=True)
    ap.add_argument("--defect", help=f"one of: {', '.join(known.BY_ID)}")
    args = ap.parse_args(argv)
    if args.defect and args.defect not in known.BY_ID:
        ap.error(f"unknown defect {args.defect!r}")
    d = json.loads(args.case.read_text())
    if args.defect:
        d["defect"] = args.defect
    else:
        d.pop("defect", None)
    out = REGRESSIONS / f"{args.name}.json"
    out.write_text(json.dumps(d, indent=1) + "\n")
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
