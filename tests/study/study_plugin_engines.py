"""Plugin engines for the sweep's tests (``module:function`` engines): one that hangs."""

import time


def hang(data, switches, *, strategy="", seed=0, repeat=1, params=None):
    """Never returns on its own: the sweep's time limit must cut it."""
    while True:
        time.sleep(1)
