#!/usr/bin/env python
"""Instructions per ``triangulate`` call on la.poly under ``pq30``, stage by
stage, counted by valgrind's cachegrind (deterministic, unlike wall time).

    PYTHONHASHSEED=0 python scripts/stage_instructions.py [RUNS [WARMUP]]

The pipeline is run cumulatively: up to the validation (with the switches'
parsing), up to ``mesh_input``, up to ``refine.run``, and whole
(``triangulate``); each process is counted twice, with WARMUP + RUNS calls
and with WARMUP, as ``instruction_count.py`` does (defaults: 20 after 3),
and each stage's figure is the difference from the one before.  ``--child
STAGE CALLS`` is the measured process itself.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile

STAGES = ("validate", "mesh_input", "refine", "full")


def _child(stage: str, calls: int) -> None:
    import triangle

    from instrument import counters, pipeline, refine
    from instrument.output import assemble
    from instrument.switches import parse

    data = triangle.get_data("la")
    for _ in range(calls):
        if stage == "full":
            pipeline.triangulate(data, "pq30", threads=1)
            continue
        o = parse("pq30")
        inp = pipeline.validate(data, o)
        if stage == "validate":
            continue
        room = refine.starting_room(inp["vertices"].shape[0], o)
        ms = pipeline.mesh_input(inp, o, counters.new_work(), threads=1, room=room)
        if stage == "mesh_input":
            continue
        refine.run(ms, o)
        if stage == "refine":
            continue
        assemble(ms, inp, o)


def _count(stage: str, calls: int, out: str) -> int:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    subprocess.run(
        ["valgrind", "--tool=cachegrind", "--cache-sim=no", f"--cachegrind-out-file={out}",
         sys.executable, __file__, "--child", stage, str(calls)],
        check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    with open(out) as f:
        for line in f:
            if line.startswith("summary:"):
                return int(line.split()[1])
    raise RuntimeError(f"no summary in {out}")


def main(argv: list[str]) -> int:
    if argv and argv[0] == "--child":
        _child(argv[1], int(argv[2]))
        return 0
    runs = int(argv[0]) if argv else 20
    warmup = int(argv[1]) if len(argv) > 1 else 3
    before = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for stage in STAGES:
            long = _count(stage, warmup + runs, os.path.join(tmp, "long.out"))
            short = _count(stage, warmup, os.path.join(tmp, "short.out"))
            upto = (long - short) / runs
            name = "assemble and the rest" if stage == "full" else stage
            print(f"{name:>22}: {upto - before:>12,.0f}   (cumulative {upto:,.0f})")
            before = upto
    print(f"la pq30, {runs} calls after {warmup}, instructions per call")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
