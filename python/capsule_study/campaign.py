"""A campaign's results (docs/guide/campaigns.md "Results layout") as one pandas row per
member, and signac-style queries over the members' scenes."""
from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

import h5py
import numpy as np
import pandas as pd

_FOLDER = re.compile(r"^(?P<slug>.+)-(?P<id>[0-9a-f]{16})$")


def _flatten(tree, prefix=""):
    """{"resolution": {"a": 7}} -> {"resolution.a": 7}; lists stay values."""
    out = {}
    for key, value in tree.items():
        name = prefix + key
        if isinstance(value, dict):
            out.update(_flatten(value, name + "."))
        else:
            out[name] = value
    return out


def _lookup(scene, dotted):
    node = scene
    for part in dotted.split("."):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(dotted)
        node = node[part]
    return node


def results_folder(path, results=None) -> Path:
    """The folder results/<name> of a campaign file, or path itself when it is one."""
    path = Path(path)
    if path.is_dir():
        if (path / "members").is_dir() or (path / "campaign.json").is_file():
            return path
        raise ValueError(f"{path}: not a campaign's results folder (no members/ and no campaign.json)")
    if not path.is_file():
        raise FileNotFoundError(f"{path}: no such campaign file or results folder")
    try:
        name = json.loads(path.read_text())["name"]
    except (ValueError, KeyError) as e:
        raise ValueError(f"{path}: not a campaign file (a JSON object with a name): {e}") from None
    if results is not None:
        candidates = [Path(results) / name]
    else:  # as study does (--results results), then beside the campaign file's repository
        candidates = [Path("results") / name, path.parent] + [p / "results" / name for p in path.resolve().parents]
    for c in candidates:
        if (c / "members").is_dir() and (c.name == name):
            return c
    raise FileNotFoundError(f"{path}: campaign {name} has no results folder (looked in "
                            + ", ".join(str(c) for c in candidates[:3]) + ", ...); run `study run` first")


def _swept_keys(campaign):
    """The scene keys a campaign file varies: its sweep's and every case's set and sweep."""
    keys = []

    def add(names):
        for k in names:
            if k not in keys:
                keys.append(k)

    def sweep(block):
        for part in ("grid", "zip"):
            add((block or {}).get(part, {}).keys())

    sweep(campaign.get("sweep"))
    for case in campaign.get("cases", []):
        add(_flatten(case.get("set", {})).keys())
        sweep(case.get("sweep"))
    return keys


def _member_folders(folder: Path):
    members = folder / "members"
    if not members.is_dir():
        return []
    return sorted(p for p in members.iterdir() if p.is_dir() and _FOLDER.match(p.name))


def _read_h5(folder: Path):
    """status, wall_seconds and markers of a member folder's file, cheaply (attributes only)."""
    for name, partial in (("member.h5", False), ("member.h5.partial", True)):
        path = folder / name
        if path.exists():
            with h5py.File(path, "r") as f:
                status = f.attrs.get("status", "")
                status = status.decode() if isinstance(status, bytes) else str(status)
                markers = {k: float(v) for k, v in f["markers"].attrs.items()} if "markers" in f else {}
                wall = float(f.attrs["wall_seconds"]) if "wall_seconds" in f.attrs else math.nan
            return ("partial: " + status if partial else status), wall, markers, str(path)
    return "not run", math.nan, {}, ""


def load_campaign(path, results=None) -> pd.DataFrame:
    """One row per member of a campaign: case, slug, member_id, status, the swept scene keys,
    the markers, and per fitted parameter its value and 95 % interval (`response.k_tau_s`,
    `response.k_tau_s.ci95_low`, `response.k_tau_s.ci95_high`, and `response.reason` where a
    fit failed) from report/fits.json when the campaign has a report.

    path: a campaign file (its results are looked up under `results`, default ./results, then
    beside the file's repository) or a results/<name> folder.
    """
    folder = results_folder(path, results)
    campaign = {}
    if (folder / "campaign.json").is_file():
        campaign = json.loads((folder / "campaign.json").read_text())
    elif Path(path).is_file():
        campaign = json.loads(Path(path).read_text())
    fits = {}
    fits_file = folder / "report" / "fits.json"
    if fits_file.is_file():
        fits = {m["id"]: m for m in json.loads(fits_file.read_text()).get("members", [])}
    keys = _swept_keys(campaign)
    for m in fits.values():
        for k in m.get("parameters", {}):
            if k not in keys:
                keys.append(k)
    cases = sorted((c["name"] for c in campaign.get("cases", [])), key=len, reverse=True)

    rows = []
    for member in _member_folders(folder):
        match = _FOLDER.match(member.name)
        slug, member_id = match["slug"], match["id"]
        scene_file = member / "scene.json"
        scene = json.loads(scene_file.read_text()) if scene_file.is_file() else {}
        fit = fits.get(member_id, {})
        case = fit.get("case")
        if case is None:
            case = next((c for c in cases if slug == c or slug.startswith(c + "-")), "")
        status, wall, markers, h5 = _read_h5(member)
        row = {"case": case, "slug": slug, "member_id": member_id, "status": status}
        for k in keys:
            try:
                value = _lookup(scene, k)
            except KeyError:
                value = None
            row[k] = tuple(value) if isinstance(value, list) else value
        row.update(markers)
        for fit_name, result in fit.get("fits", {}).items():
            if not result.get("ok", False):
                row[fit_name + ".reason"] = result.get("reason", "the fit failed")
                continue
            for p in result.get("parameters", []):
                low, high = (p.get("ci95") or [math.nan, math.nan])[:2]
                row[f"{fit_name}.{p['name']}"] = p.get("value", math.nan)
                row[f"{fit_name}.{p['name']}.ci95_low"] = low
                row[f"{fit_name}.{p['name']}.ci95_high"] = high
        row["wall_seconds"] = wall
        row["path"] = h5
        rows.append(row)
    frame = pd.DataFrame(rows)
    frame.attrs["campaign"] = campaign.get("name", folder.name)
    frame.attrs["results_folder"] = str(folder)
    return frame


# ---------------------------------------------------------------- queries

def _equal(a, b):
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b or a == b
    if isinstance(a, (int, float, np.number)) and isinstance(b, (int, float, np.number)):
        return math.isclose(float(a), float(b), rel_tol=1e-12, abs_tol=0.0)
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b))
    return a == b


_OPERATORS = {
    "$eq": _equal,
    "$ne": lambda a, b: not _equal(a, b),
    "$gt": lambda a, b: a > b,
    "$gte": lambda a, b: a > b or _equal(a, b),
    "$lt": lambda a, b: a < b,
    "$lte": lambda a, b: a < b or _equal(a, b),
    "$in": lambda a, b: any(_equal(a, x) for x in b),
    "$nin": lambda a, b: not any(_equal(a, x) for x in b),
}


def _matches(scene, query):
    for key, wanted in query.items():
        try:
            value = _lookup(scene, key)
            present = True
        except KeyError:
            value, present = None, False
        if isinstance(wanted, dict) and wanted and all(k.startswith("$") for k in wanted):
            for op, operand in wanted.items():
                if op == "$exists":
                    if present != bool(operand):
                        return False
                    continue
                if op not in _OPERATORS:
                    raise ValueError(f"find_members: unknown operator {op} on {key} "
                                     f"(allowed: {', '.join(sorted(_OPERATORS))}, $exists)")
                if not present:
                    return False
                try:
                    if not _OPERATORS[op](value, operand):
                        return False
                except TypeError:
                    return False
        elif not present or not _equal(value, wanted):
            return False
    return True


def find_members(results, filter=None, **query):
    """The member folders under `results` whose scene matches every condition, sorted.

    results: a results root (results/), one campaign's results folder, or a campaign file.
    Conditions on scene keys, dotted for nested ones: find_members("results", Ca=0.1) or
    find_members("results/ch3_ca", {"resolution.a": 7, "Ca": {"$lte": 0.05}}); a keyword's
    double underscore stands for the dot (resolution__a=7). Operators as in signac: $eq, $ne,
    $gt, $gte, $lt, $lte, $in, $nin, $exists. Numbers compare equal within 1e-12 relative.
    """
    conditions = dict(filter or {})
    conditions.update({k.replace("__", "."): v for k, v in query.items()})
    root = Path(results)
    if root.is_file():
        folders = [results_folder(root)]
    elif (root / "members").is_dir():
        folders = [root]
    elif root.is_dir():
        folders = sorted(p for p in root.iterdir() if (p / "members").is_dir())
    else:
        raise FileNotFoundError(f"{results}: no such results folder or campaign file")
    found = []
    for folder in folders:
        for member in _member_folders(folder):
            scene_file = member / "scene.json"
            if scene_file.is_file() and _matches(json.loads(scene_file.read_text()), conditions):
                found.append(member)
    return found
