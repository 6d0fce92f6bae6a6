"""One member file (docs/guide/member-files.md) as an xarray Dataset and plain dicts."""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field

import h5py
import numpy as np
import xarray as xr

from .quantities import MARKERS, SERIES


@dataclass
class Member:
    """What load_member returns.

    series: xarray.Dataset, one variable per series, the coordinate kt (beta has a second
        dimension, `tracked`); every variable has the attributes units and description.
    markers: {name: value} (NaN where not reached); marker_units, marker_descriptions alike.
    scene: the canonical scene (every default filled in), a dict.
    status: "complete", "unstable at kt = X: reason", "stopped: reason" or "running".
    attrs: every root attribute (scene as its JSON text).
    shapes: the stored shapes (output.shapes_at_kt), a list of (kt, positions [nodes x dim] in
        lattice units, as quantities.SHAPES says); triangles: [m x 3] node indices in 3D, or None.
    """
    path: str
    status: str
    scene: dict
    series: xr.Dataset
    markers: dict
    marker_units: dict
    marker_descriptions: dict
    attrs: dict = field(repr=False)
    shapes: list = field(default_factory=list, repr=False)
    triangles: np.ndarray = field(default=None, repr=False)

    @property
    def complete(self) -> bool:
        return self.status == "complete"

    @property
    def member_id(self) -> str:
        return self.attrs.get("member_id", "")


def _text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, np.generic):
        return value.item()
    return value


def _describe(name, attrs, table, path):
    """units and description from the file's attributes, or from the table for older files."""
    units, description = attrs.get("units"), attrs.get("description")
    if units is None or description is None:
        if name not in table:
            raise KeyError(f"{path}: {name} has no units in the file and none in capsule_study.quantities")
        units = units if units is not None else table[name][0]
        description = description if description is not None else table[name][1]
    return _text(units), _text(description)


def load_member(path) -> Member:
    """Reads a member file (member.h5 or member.h5.partial) or a member folder holding one."""
    path = os.fspath(path)
    if os.path.isdir(path):
        for name in ("member.h5", "member.h5.partial"):
            if os.path.exists(os.path.join(path, name)):
                path = os.path.join(path, name)
                break
        else:
            raise FileNotFoundError(f"{path}: no member.h5 or member.h5.partial in this folder")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such member file")
    with h5py.File(path, "r") as f:
        attrs = {k: _text(v) for k, v in f.attrs.items()}
        if "status" not in attrs:
            raise ValueError(f"{path}: no status attribute: not a member file")
        scene = json.loads(attrs["scene"]) if "scene" in attrs else {}
        data_vars, kt = {}, None
        if "series" in f and "kt" in f["series"]:
            kt = f["series/kt"][:]
        for name, ds in (f["series"].items() if "series" in f else []):
            if name == "kt":
                continue
            values = ds[:]
            dims = ("kt",) if values.ndim == 1 else ("kt", "tracked")
            units, description = _describe(name, ds.attrs, SERIES, path)
            data_vars[name] = xr.Variable(dims, values, {"units": units, "description": description})
        coords = {}
        if kt is not None:
            units, description = _describe("kt", f["series/kt"].attrs, SERIES, path)
            coords["kt"] = xr.Variable(("kt",), kt, {"units": units, "description": description})
        markers, marker_units, marker_descriptions = {}, {}, {}
        if "markers" in f:
            g = f["markers"]
            for name, value in g.attrs.items():
                markers[name] = float(value)
                about = {key: g[key].attrs[name] for key in ("units", "description")
                         if key in g and name in g[key].attrs}
                marker_units[name], marker_descriptions[name] = _describe(name, about, MARKERS, path)
        shapes, triangles = [], None
        for name, ds in (f["shapes"].items() if "shapes" in f else []):
            if name == "triangles":
                triangles = ds[:]
            else:
                shapes.append((float(ds.attrs.get("kt", np.nan)), ds[:]))
    series = xr.Dataset(data_vars, coords=coords,
                        attrs={"member_id": attrs.get("member_id", ""), "status": attrs["status"], "path": path})
    return Member(path=path, status=attrs["status"], scene=scene, series=series, markers=markers,
                  marker_units=marker_units, marker_descriptions=marker_descriptions, attrs=attrs,
                  shapes=shapes, triangles=triangles)


