"""Shared paths for the capsule_study tests: the repository (two folders up) and its shipped
campaign ch3_ca, the one every test reads (2D and 3D members, a report with fits)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

TOP = Path(__file__).resolve().parents[2]
CH3_CA = TOP / "results" / "ch3_ca"


@pytest.fixture(scope="session")
def top():
    return TOP


@pytest.fixture(scope="session")
def ch3_ca():
    assert (CH3_CA / "members").is_dir(), f"{CH3_CA}: the shipped campaign is missing"
    return CH3_CA


def capsule_binary():
    """The capsule binary: $CAPSULE_BINARY (CTest sets it, and then it must exist), else the
    default build's; None when there is neither (the fresh-member tests then skip)."""
    named = os.environ.get("CAPSULE_BINARY")
    if named:
        assert os.access(named, os.X_OK), f"CAPSULE_BINARY={named} is not an executable"
        return named
    built = TOP / "build" / "solver" / "capsule"
    return str(built) if os.access(built, os.X_OK) else None


@pytest.fixture(scope="session")
def fresh_members(tmp_path_factory):
    """A 2D and a 3D member written now by this build's capsule (CI-sized scenes: seconds)."""
    capsule = capsule_binary()
    if capsule is None:
        pytest.skip("no capsule binary: build it (cmake --build build) or set CAPSULE_BINARY")
    out = tmp_path_factory.mktemp("fresh")
    members = {}
    for name, scene in (("2d", "circle_quick_2d.json"), ("3d", "sphere_snapshots_3d.json")):
        text = json.loads((TOP / "tests" / "data" / "scenes" / scene).read_text())
        if name == "2d":  # shortened: a few output rows under shear and after the stop suffice
            text["protocol"] = {"shear": {"until": "time", "kt": 0.2}, "recover": {"until": "time", "kt": 0.1}}
            text["output"]["shapes_at_kt"] = [0, 0.2]
        path = out / name / "member.h5"
        path.parent.mkdir()
        (out / name / "scene.json").write_text(json.dumps(text))
        run = subprocess.run([capsule, str(out / name / "scene.json"), "-o", str(path), "-q"],
                             capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, run.stderr[-800:]
        members[name] = path
    return members
