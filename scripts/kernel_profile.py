#!/usr/bin/env python
"""Where the engine's kernels spend their time, instruction by instruction (Linux, ``perf``).

    python scripts/kernel_profile.py                      # the unit square, pq30a0.000001
    python scripts/kernel_profile.py dt-1e6 --top 8 --disassemble 3
    python scripts/kernel_profile.py la-q30 --repeat 500  # small inputs: many runs

``scripts/bench.py --profile`` times whole kernel calls; inside a kernel
neither cProfile nor perf can name anything, because numba's machine code has
no symbols perf can see.  This script runs ``instrument.triangulate`` on one
of ``scripts/bench.py``'s workloads (the unit square unless told) under
``perf record`` with a fresh numba cache (so every dispatcher is compiled in
the process and keeps its object code), writes each dispatcher's object
file, and maps every sample that landed in numba's code back to the
dispatcher whose library holds it and to an offset in that object file.  It
prints the share of each dispatcher (its inlined callees included) and the
hottest 64-byte blocks, and disassembles the top ones with the sample counts
beside the instructions.

Compiling everything afresh takes about a minute before the run starts.
"""

from __future__ import annotations

import argparse
import bisect
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

# The child: run the workload, then dump each compiled library's object code
# and the run-time address of its entry function.
CHILD = r"""
import gc, json, sys, time
sys.path.insert(0, "scripts")
import instrument
from bench import WORKLOADS
from numba.core.registry import CPUDispatcher
out, name, repeat = sys.argv[1], sys.argv[2], int(sys.argv[3])
w = WORKLOADS[name]
data = w.make()
instrument.triangulate(data, w.opts)  # compile outside the measured runs
t = time.perf_counter()
for _ in range(repeat):
    r = instrument.triangulate(data, w.opts)
print(f"{name}: {(time.perf_counter() - t) / repeat:.4f} s a run, {len(r['triangles'])} triangles", file=sys.stderr)
libs = []
for d in gc.get_objects():
    if isinstance(d, CPUDispatcher):
        for cres in d.overloads.values():
            code = cres.library._compiled_object
            if code:
                path = f"{out}/{len(libs)}.o"
                open(path, "wb").write(code)
                name = cres.fndesc.llvm_func_name
                libs.append({"file": path, "name": name, "addr": cres.library.get_pointer_to_function(name),
                             "function": d.py_func.__module__ + "." + d.py_func.__qualname__})
json.dump(libs, open(f"{out}/libs.json", "w"))
"""


def run(cmd: list[str], **kw) -> str:
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw).stdout


def code_ranges(libs: list[dict]) -> list[tuple[int, int, dict]]:
    """(start, end, library) of each object's code section in memory."""
    ranges = []
    for lib in libs:
        symbols = {p[3]: int(p[0], 16) for p in (line.split() for line in run(["nm", "-S", "--defined-only", lib["file"]]).splitlines()) if len(p) >= 4}
        sections = re.findall(r"\]\s+(\S+)\s+PROGBITS\s+\S+\s+\S+\s+([0-9a-f]+)\s+\S+\s+AX", run(["readelf", "-S", "-W", lib["file"]]))
        size = sum(int(s, 16) for name, s in sections if name.endswith("text"))
        if lib["name"] in symbols:
            start = lib["addr"] - symbols[lib["name"]]
            ranges.append((start, start + size, lib))
    return sorted(ranges, key=lambda r: r[0])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench import WORKLOADS

    ap.add_argument("workload", nargs="?", default="square-q30a1e-6", choices=[n for n, w in WORKLOADS.items() if w.make],
                    help="a workload of scripts/bench.py (default square-q30a1e-6)")
    ap.add_argument("--repeat", type=int, default=1, help="runs of the workload under perf (default 1)")
    ap.add_argument("--top", type=int, default=15, help="hot blocks to list (default 15)")
    ap.add_argument("--disassemble", type=int, default=2, help="hot blocks to disassemble (default 2)")
    ap.add_argument("--frequency", type=int, default=1999, help="perf's sampling frequency in Hz (default 1999)")
    args = ap.parse_args()
    for tool in ("perf", "nm", "readelf", "objdump"):
        if shutil.which(tool) is None:
            print(f"Error: {tool} is not installed", file=sys.stderr)
            return 1
    with tempfile.TemporaryDirectory(prefix="ruppert-kprof-") as tmp:
        env = dict(os.environ, NUMBA_CACHE_DIR=f"{tmp}/numba")
        data = f"{tmp}/perf.data"
        subprocess.run(["perf", "record", "-q", "-F", str(args.frequency), "-o", data, sys.executable, "-c", CHILD, tmp,
                        args.workload, str(args.repeat)], check=True, env=env, cwd=Path(__file__).resolve().parents[1])
        libs = json.load(open(f"{tmp}/libs.json"))
        ranges = code_ranges(libs)
        starts = [r[0] for r in ranges]
        per_function, blocks, total = Counter(), Counter(), 0
        ips = [int(line, 16) for line in run(["perf", "script", "-i", data, "-F", "ip"]).split()]
        for ip in ips:
            i = bisect.bisect_right(starts, ip) - 1
            if i >= 0 and ip < ranges[i][1]:
                total += 1
                lib = ranges[i][2]
                per_function[lib["function"]] += 1
                blocks[(lib["function"], lib["file"], (ip - ranges[i][0]) // 64 * 64)] += 1
        if not total:
            print("no samples in numba's code")
            return 1
        print(f"{total} samples in numba's code ({total / args.frequency:.2f} s at {args.frequency} Hz)\n")
        print("share  dispatcher (inlined callees included)")
        for name, n in per_function.most_common():
            print(f"{100 * n / total:5.1f}  {name}")
        print("\nshare  hottest 64-byte blocks")
        for (name, _, off), n in blocks.most_common(args.top):
            print(f"{100 * n / total:5.1f}  {name} +{off:#x}")
        for (name, path, off), _ in blocks.most_common(args.disassemble):
            start = next(r[0] for r in ranges if r[2]["file"] == path)
            lo, hi = max(0, off - 64), off + 128
            hits = Counter(ip - start for ip in ips if lo <= ip - start < hi)
            print(f"\n{name} +{lo:#x} .. +{hi:#x} (samples, offset, instruction):")
            listing = run(["objdump", "-d", "--no-show-raw-insn", path, f"--start-address={lo}", f"--stop-address={hi}"])
            for m in re.finditer(r"^\s+([0-9a-f]+):\s+(.*)$", listing, re.M):
                at = int(m.group(1), 16)
                print(f"{hits.get(at, ''):>6} {at:6x}  {re.sub(r'<[^>]*>', '', m.group(2))[:80]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
