"""``python -m instrument.study``: what the parts are and how to run them."""

import sys

from . import __doc__ as _doc

if __name__ == "__main__":
    sys.stdout.write(_doc.strip() + "\n")
