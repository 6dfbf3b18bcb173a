"""A sweep's results: one Parquet dataset, one row per task, written as tasks finish.

Layout of a dataset directory:

* ``part-<time>-<id>.parquet``: rows, in the schema ``SCHEMA``; a running
  sweep adds a file every second or so (and at the end), so an interrupted
  sweep keeps what it finished; ``compact`` merges them when a run ends;
* ``inputs.json``: the inputs the sweep read (label, digest, sizes), and the
  ones it could not read, with the reason;
* ``meshes/<key>.npz``: output meshes, when the sweep was asked to keep them.

The row key is a hash of what determines a measurement: the input (label and
digest), the switches asked for, the engine, the strategy, the seed and the
number of timed runs.  Limits are not in it: a row that timed out stays
done until the sweep is told to ``redo`` its status.  Reading keeps the
newest row of each key, so a row measured again replaces the old one.
"""

from __future__ import annotations

import datetime as dt
import hashlib
import json
import os
import time
import uuid
from collections.abc import Iterable, Mapping
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

COUNTS = pa.map_(pa.string(), pa.int64())
MEASURES = pa.map_(pa.string(), pa.float64())

SCHEMA = pa.schema([
    ("key", pa.string()),
    ("input", pa.string()),
    ("family", pa.string()),
    ("source", pa.string()),
    ("digest", pa.string()),
    ("params", MEASURES),
    ("switches", pa.string()),  # as asked
    ("ran_switches", pa.string()),  # as run (a point set loses p)
    ("engine", pa.string()),
    ("strategy", pa.string()),
    ("seed", pa.int64()),
    ("repeat", pa.int64()),
    ("status", pa.string()),  # ok unsupported unavailable error memory timeout crash skipped
    ("message", pa.string()),
    ("note", pa.string()),
    ("input_vertices", pa.int64()),
    ("input_segments", pa.int64()),
    ("vertices", pa.int64()),
    ("triangles", pa.int64()),
    ("segments", pa.int64()),
    ("min_angle", pa.float64()),
    ("max_angle", pa.float64()),
    ("area", pa.float64()),
    ("triangles_created", pa.int64()),
    ("incircle_tests", pa.int64()),
    ("orient_tests", pa.int64()),
    ("circumcenters", pa.int64()),
    ("steiner_points", pa.int64()),
    ("work", COUNTS),  # every counter the engine reports
    ("metrics", MEASURES),  # the input family's measures of the output
    ("wall_s", pa.float64()),  # the engine's best timed run
    ("task_s", pa.float64()),  # the whole task, process start and statistics runs included
    ("peak_mb", pa.float64()),  # the engine's process: resident-set peak during the task
    ("base_mb", pa.float64()),  # ... and its resident set before it
    ("time_limit_s", pa.float64()),
    ("memory_limit_mb", pa.float64()),
    ("series", pa.string()),
    ("order", pa.float64()),
    ("worker", pa.string()),
    ("finished", pa.timestamp("us", tz="UTC")),
    ("versions", pa.string()),
])
COLUMNS = tuple(SCHEMA.names)
#: statuses after which a row is not run again (unless redone)
FINAL = ("ok", "unsupported", "unavailable", "error", "memory", "timeout", "crash")


def row_key(input_label: str, digest: str, switches: str, engine: str, strategy: str, seed: int, repeat: int) -> str:
    text = json.dumps([input_label, digest, switches, engine, strategy, int(seed), int(repeat)])
    return hashlib.sha256(text.encode()).hexdigest()[:20]


def normalized(row: Mapping) -> dict:
    """``row`` with every column of the schema (None where absent), stamped when it finished."""
    out = {k: row.get(k) for k in COLUMNS}
    if out["finished"] is None:
        out["finished"] = dt.datetime.now(dt.UTC)
    return out


def append(path: Path, rows: Iterable[Mapping]) -> Path | None:
    """Write ``rows`` as one new file of the dataset; None if there are none."""
    rows = [normalized(r) for r in rows]
    if not rows:
        return None
    path = Path(path)
    path.mkdir(parents=True, exist_ok=True)
    name = path / f"part-{time.time_ns()}-{uuid.uuid4().hex[:8]}.parquet"
    tmp = name.with_suffix(".tmp")
    pq.write_table(pa.Table.from_pylist(rows, schema=SCHEMA), tmp)
    os.replace(tmp, name)  # readers never see half a file
    return name


def parts(path: Path) -> list[Path]:
    path = Path(path)
    return sorted(path.glob("part-*.parquet")) if path.is_dir() else []


def _dict(value) -> dict:
    return {} if value is None else dict(value)


def read(path: Path) -> list[dict]:
    """Every row, the newest per key, in the order they finished."""
    newest: dict[str, dict] = {}
    for part in parts(path):
        for row in pq.read_table(part, schema=SCHEMA).to_pylist():
            for k in ("params", "work", "metrics"):
                row[k] = _dict(row[k])
            old = newest.get(row["key"])
            if old is None or row["finished"] >= old["finished"]:
                newest[row["key"]] = row
    return sorted(newest.values(), key=lambda r: r["finished"])


def statuses(path: Path) -> dict[str, str]:
    """Key -> status of every row (only the two columns are read)."""
    out: dict[str, tuple] = {}
    for part in parts(path):
        t = pq.read_table(part, columns=["key", "status", "finished"])
        for key, status, when in zip(*(t.column(c).to_pylist() for c in ("key", "status", "finished")), strict=True):
            if key not in out or when >= out[key][1]:
                out[key] = (status, when)
    return {k: v[0] for k, v in out.items()}


def compact(path: Path) -> None:
    """Merge the dataset's files into one (the newest row per key)."""
    old = parts(path)
    if len(old) < 2:
        return
    rows = read(path)
    append(path, rows)
    for p in old:
        p.unlink()


def write_inputs(path: Path, catalog: list[dict]) -> None:
    """Merge ``catalog`` into ``inputs.json`` (one entry per label and digest)."""
    path = Path(path)
    path.mkdir(parents=True, exist_ok=True)
    merged = {(c["label"], c["digest"]): c for c in read_inputs(path)}
    merged.update({(c["label"], c["digest"]): c for c in catalog})
    text = json.dumps(list(merged.values()), indent=1) + "\n"
    f = path / "inputs.json"
    if not f.exists() or f.read_text() != text:  # unchanged: left alone, so a summary of it stays current
        f.write_text(text)


def read_inputs(path: Path) -> list[dict]:
    f = Path(path) / "inputs.json"
    return json.loads(f.read_text()) if f.is_file() else []


def mesh_path(path: Path, key: str) -> Path:
    return Path(path) / "meshes" / f"{key}.npz"
