"""The package's table of units and descriptions is the solver's: row by row against
solver/io/quantities.cpp, and against what a member file written now by capsule says (every
series and marker carries units and description, and kt is the series' dimension scale)."""
import re

import h5py
import numpy as np

import capsule_study as cs


def cpp_tables(top):
    text = (top / "solver" / "io" / "quantities.cpp").read_text()
    series, rest = text.split("marker_quantities()", 1)
    markers, shapes = rest.split("shape_quantities()", 1)
    row = re.compile(r'\{"([^"]+)", "([^"]*)",\s*"([^"]*)"\}')
    return tuple({n: (u, d) for n, u, d in row.findall(part)} for part in (series, markers, shapes))


def test_the_table_is_the_solvers(top):
    series, markers, shapes = cpp_tables(top)
    assert len(series) > 20 and len(markers) == 8 and len(shapes) == 2
    assert cs.SERIES == series
    assert cs.MARKERS == markers
    assert cs.SHAPES == shapes


def test_fresh_member_files_describe_themselves(fresh_members):
    seen = set()
    for dim, path in fresh_members.items():
        with h5py.File(path, "r") as f:
            kt = f["series/kt"]
            assert h5py.h5ds.is_scale(kt.id) and kt.attrs["NAME"] == b"kt"
            for name, ds in f["series"].items():
                seen.add(name)
                assert (ds.attrs["units"], ds.attrs["description"]) == cs.SERIES[name], name
                if name != "kt":  # h5py sees the time coordinate of every series
                    assert ds.dims[0][0] == kt, name
            for name, ds in f["shapes"].items():
                row = "triangles" if name == "triangles" else "positions"
                assert (ds.attrs["units"], ds.attrs["description"]) == cs.SHAPES[row], name
            assert ("triangles" in f["shapes"]) == (dim == "3d")
            g = f["markers"]
            assert set(g.attrs) == set(cs.MARKERS)
            for name in g.attrs:
                assert (g["units"].attrs[name], g["description"].attrs[name]) == cs.MARKERS[name]
        m = cs.load_member(path)  # the file's own attributes, the same as the table
        for name in m.series.variables:
            assert (m.series[name].attrs["units"], m.series[name].attrs["description"]) == cs.SERIES[name]
        assert m.series.sizes["kt"] == len(m.series["kt"]) > 1
        assert m.status == "complete"
        np.testing.assert_allclose([kt for kt, _ in m.shapes], [0.0, 0.2] if dim == "2d" else [0.0, 0.1, 0.2])
        assert m.shapes[0][1].shape[1] == (2 if dim == "2d" else 3)
        assert (m.triangles is not None) == (dim == "3d")
    # Every row of the table but the power law's surface shear rates and the stretch protocol's
    # columns (tests/solver/run/stretch3d_test.cpp) is written by one of them.
    assert set(cs.SERIES) - seen == {"gamma_min", "gamma_max", "force_on", "D_axial", "D_transverse",
                                     "D_axial_um", "D_transverse_um"}
