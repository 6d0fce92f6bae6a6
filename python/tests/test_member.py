"""load_member on shipped member files (written before files described themselves: units from
the package's table) and on member folders."""
import json
import math

import h5py
import numpy as np
import pytest

import capsule_study as cs


def one(folder, prefix):
    return next(p for p in sorted((folder / "members").iterdir()) if p.name.startswith(prefix))


@pytest.mark.parametrize("prefix", ["2d-Ca0.1-", "3d-Ca0.1-a7-"])
def test_series_markers_scene_as_in_the_file(ch3_ca, prefix):
    folder = one(ch3_ca, prefix)
    m = cs.load_member(folder / "member.h5")
    with h5py.File(folder / "member.h5", "r") as f:
        kt = f["series/kt"][:]
        np.testing.assert_array_equal(m.series["kt"].values, kt)
        for name, ds in f["series"].items():
            np.testing.assert_array_equal(m.series[name].values, ds[:])
        assert m.markers == {k: float(v) for k, v in f["markers"].attrs.items()}
        assert m.status == f.attrs["status"] == "complete"
        assert m.scene == json.loads(f.attrs["scene"])
    assert list(m.series.coords) == ["kt"] and m.series["D_xy"].dims == ("kt",)
    assert m.scene["Ca"] == 0.1
    assert m.member_id == folder.name.rsplit("-", 1)[1]
    # The series is indexable by time: the largest D_xy under shear is the marker D_max.
    under_shear = m.series["D_xy"].where(m.series["shear_on"] == 1, drop=True)
    assert math.isclose(float(under_shear.max()), m.markers["D_max"], rel_tol=1e-12)
    assert math.isclose(float(under_shear.idxmax()), m.markers["t_max"], rel_tol=1e-12)


def test_units_of_files_written_before_from_the_table(ch3_ca):
    m = cs.load_member(one(ch3_ca, "3d-Ca0.1-a7-"))  # the folder is accepted too
    with h5py.File(m.path, "r") as f:
        assert "units" not in f["series/D_xy"].attrs  # a shipped file: no units of its own
    for name in list(m.series.data_vars) + ["kt"]:
        assert (m.series[name].attrs["units"], m.series[name].attrs["description"]) == cs.SERIES[name]
    assert m.series["beta"].dims == ("kt", "tracked") and m.series["beta"].shape[1] == 5
    assert m.series["L"].attrs["units"] == "a" and m.series["kt"].attrs["units"] == "1/k"
    assert m.marker_units == {k: cs.MARKERS[k][0] for k in m.markers}
    assert m.marker_descriptions == {k: cs.MARKERS[k][1] for k in m.markers}


def test_a_missing_or_foreign_file_is_named(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such member file"):
        cs.load_member(tmp_path / "member.h5")
    with pytest.raises(FileNotFoundError, match="no member.h5"):
        cs.load_member(tmp_path)
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f["x"] = [1.0]
    with pytest.raises(ValueError, match="other.h5: no status attribute"):
        cs.load_member(tmp_path / "other.h5")
