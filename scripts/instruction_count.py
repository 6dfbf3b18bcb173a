#!/usr/bin/env python
"""Instructions per ``triangulate`` call, counted by valgrind's cachegrind:
deterministic, unlike wall time on a shared machine.

    python scripts/instruction_count.py ENGINE CASE [RUNS [WARMUP]]

ENGINE is ``ours`` (``instrument.triangulate``, ``threads=1``) or
``triangle`` (the `triangle` package); CASE one of ``la`` (la.poly from the
package's data, ``pq30``), ``square`` (the unit square, ``pq30a0.000001``)
or ``triangle`` (one triangle with its three sides as segments, ``pq30``).
The script runs the process twice under cachegrind, once with WARMUP + RUNS
calls and once with WARMUP, and prints the difference over RUNS: start-up,
imports and the first calls cancel out (defaults: 50 runs after 5; the
square takes 1 after 0, some minutes under valgrind).

It also prints the count without libc's memset and memcpy: valgrind counts
each byte of their ``rep stos``/``rep movs`` as an instruction, so a 64 KB
clear counts 65,536 instructions where the processor spends a few thousand
cycles (both engines clear and copy memory; the difference is shown, not
hidden).

``--child`` is the measured process itself (the calls, nothing else).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile

CASES = ("la", "square", "triangle")


def _case(name: str):
    import numpy as np
    import triangle

    if name == "la":
        return triangle.get_data("la"), "pq30"
    if name == "square":
        square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        return {"vertices": square, "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]])}, "pq30a0.000001"
    one = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    return {"vertices": one, "segments": np.array([[0, 1], [1, 2], [2, 0]])}, "pq30"


def _child(engine: str, case: str, calls: int) -> None:
    data, opts = _case(case)
    if engine == "ours":
        import instrument

        for _ in range(calls):
            instrument.triangulate(data, opts, threads=1)
    else:
        import triangle

        for _ in range(calls):
            triangle.triangulate(data, opts)


def _count(engine: str, case: str, calls: int, out: str) -> tuple[int, int]:
    """(all instructions, those outside memset and memcpy) of a process making ``calls`` calls."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")  # (numpy's thread pool starts threads otherwise)
    subprocess.run(
        ["valgrind", "--tool=cachegrind", "--cache-sim=no", f"--cachegrind-out-file={out}",
         sys.executable, __file__, "--child", engine, case, str(calls)],
        check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    total = rep = 0
    fn = ""
    with open(out) as f:
        for line in f:
            if line.startswith("fn="):
                fn = line[3:]
            elif line.startswith("summary:"):
                total = int(line.split()[1])
            elif line[:1].isdigit() and ("memset" in fn or "memcpy" in fn or "memmove" in fn):
                rep += int(line.split()[1])
    return total, total - rep


def main(argv: list[str]) -> int:
    if argv and argv[0] == "--child":
        _child(argv[1], argv[2], int(argv[3]))
        return 0
    if len(argv) < 2 or argv[0] not in ("ours", "triangle") or argv[1] not in CASES:
        print(__doc__, file=sys.stderr)
        return 2
    engine, case = argv[0], argv[1]
    runs = int(argv[2]) if len(argv) > 2 else (1 if case == "square" else 50)
    warmup = int(argv[3]) if len(argv) > 3 else (0 if case == "square" else 5)
    with tempfile.TemporaryDirectory() as tmp:
        long = _count(engine, case, warmup + runs, os.path.join(tmp, "long.out"))
        short = _count(engine, case, warmup, os.path.join(tmp, "short.out"))
    total, plain = ((a - b) / runs for a, b in zip(long, short))
    print(f"{engine} {case}: {total:,.0f} instructions per call ({plain:,.0f} without memset/memcpy), "
          f"{runs} calls after {warmup}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
