"""A differential case (input dict + switches) and its exact JSON form.

Coordinates are written with ``float.hex()`` so a case read back is the same
input bit for bit: a regression found at 1e-300 or on a chain 1e-15 off a
line must stay that input.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

FLOAT_KEYS = ("vertices", "vertex_attributes", "holes", "regions", "triangle_max_area", "triangle_attributes")
INT_KEYS = ("vertex_markers", "segments", "segment_markers", "triangles")


@dataclass
class Case:
    """One input and one switch string (library mode, no dash).

    ``family`` names the generator; ``premesh`` (only for ``r`` cases made
    by the generator) is the switch string Triangle meshes the input with
    before it is refined, and ``area_factors`` the per-triangle area bounds
    (fractions of the bounding-box area, cycled over the triangles; <= 0 is
    no bound) given to that mesh.  ``materialized`` cases have the mesh in
    ``input`` already, and are what is written to disk.
    """

    family: str
    switches: str
    input: dict
    premesh: str | None = None
    area_factors: tuple = ()
    meta: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        out = {"family": self.family, "switches": self.switches, "input": encode_input(self.input)}
        if self.premesh:
            out["premesh"] = self.premesh
            out["area_factors"] = [float(a).hex() for a in self.area_factors]
        if self.meta:
            out["meta"] = self.meta
        return out

    @classmethod
    def from_json(cls, d: dict) -> Case:
        return cls(
            family=d["family"],
            switches=d["switches"],
            input=decode_input(d["input"]),
            premesh=d.get("premesh"),
            area_factors=tuple(float.fromhex(a) for a in d.get("area_factors", ())),
            meta=dict(d.get("meta", {})),
        )

    def describe(self) -> str:
        n = len(self.input.get("vertices", ()))
        s = len(self.input.get("segments", ()))
        return f"{self.family}: {n} vertices, {s} segments, switches {self.switches!r}"


def encode_input(tri: dict) -> dict:
    out = {}
    for k, v in tri.items():
        a = np.asarray(v)
        if k in FLOAT_KEYS:
            out[k] = {"shape": list(a.shape), "hex": [float(x).hex() for x in a.astype(np.float64).ravel()]}
        else:
            out[k] = {"shape": list(a.shape), "int": [int(x) for x in a.ravel()]}
    return out


def decode_input(d: dict) -> dict:
    out = {}
    for k, v in d.items():
        if "hex" in v:
            a = np.array([float.fromhex(x) for x in v["hex"]], dtype=np.float64)
        else:
            a = np.array(v["int"], dtype=np.int32 if k != "segments" else np.int32)
        out[k] = a.reshape(v["shape"])
    return out


def write_case(path: Path, case: Case, **extra) -> None:
    d = case.to_json() | extra
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(d, indent=1) + "\n")


def read_case(path: Path) -> tuple[Case, dict]:
    """The case and the whole JSON object (``defect``, ``triangle``, ``ours`` notes)."""
    d = json.loads(path.read_text())
    return Case.from_json(d), d
