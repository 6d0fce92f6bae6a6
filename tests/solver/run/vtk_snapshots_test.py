#!/usr/bin/env python3
"""A 3D member's snapshots open in VTK as ParaView would: `capsule` runs a small sphere with
output.snapshots "vtk"; the collection member.pvd names one .vtp file per snapshot time, and VTK's
own vtkXMLPolyDataReader loads each with the mesh (162 points, 320 triangles at mesh level 2) and
the fields: membrane_velocity (3 components), mean_curvature and turned_angle per point,
stretch_1, stretch_2, area_dilation per triangle, every array binary and zlib-compressed, the
points in units of a from the domain centre. Checks the numbers make sense: at kt 0 the
sphere is undeformed (every stretch 1, a mean curvature times a of a / r_m within the fit's error,
no turn), and under shear the membrane moves and stretches. Run by CTest (vtk_snapshots) with
Debian's python3 and python3-vtk9 (scripts/install-deps). Prints 'N passed, M failed'."""
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy

top, capsule = sys.argv[1], sys.argv[2]
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAILED:", what)


with tempfile.TemporaryDirectory() as out:
    run = subprocess.run([capsule, os.path.join(top, "tests/data/scenes/sphere_snapshots_3d.json"), "-o",
                          os.path.join(out, "member.h5"), "-q"], capture_output=True, text=True)
    check(run.returncode == 0, "capsule ran: " + run.stderr[-400:])
    with h5py.File(os.path.join(out, "member.h5"), "r") as f:
        marker_radius = float(f.attrs["marker_radius"])
    collection = ET.parse(os.path.join(out, "member.pvd")).getroot()
    sets = collection.findall("./Collection/DataSet")
    check([float(s.get("timestep")) for s in sets] == [0.0, 0.1, 0.2], "the collection holds kt 0, 0.1, 0.2")
    for s in sets:
        kt = float(s.get("timestep"))
        with open(os.path.join(out, s.get("file")), "rb") as raw:
            head = raw.read(2000)
        check(b'compressor="vtkZLibDataCompressor"' in head and b'format="appended"' in head
              and b'format="ascii"' not in head, "binary, zlib-compressed arrays at kt %g" % kt)
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(out, s.get("file")))
        reader.Update()
        poly = reader.GetOutput()
        check(poly.GetNumberOfPoints() == 162 and poly.GetNumberOfPolys() == 320, "mesh at kt %g" % kt)
        pd, cd = poly.GetPointData(), poly.GetCellData()
        fields = {}
        for data, names in ((pd, ("membrane_velocity", "mean_curvature", "turned_angle")),
                            (cd, ("stretch_1", "stretch_2", "area_dilation"))):
            for name in names:
                array = data.GetArray(name)
                check(array is not None, "%s at kt %g" % (name, kt))
                if array is not None:
                    fields[name] = vtk_to_numpy(array)
        if len(fields) < 6:
            continue
        check(fields["membrane_velocity"].shape == (162, 3), "velocity has 3 components per point")
        # Points in units of a from the domain centre (the member file's centroid_x/y/z): the
        # sphere sits at the centre with the markers' radius r_m / a (a less the marker inset).
        xyz = vtk_to_numpy(poly.GetPoints().GetData())
        r = ((xyz - xyz.mean(axis=0)) ** 2).sum(axis=1).mean() ** 0.5
        check(abs(xyz.mean(axis=0)).max() < 0.05, "centred on the domain centre at kt %g" % kt)
        if kt == 0.0:
            check(abs(r - marker_radius / 4.0) < 1e-3, "radius %g = marker_radius / a at the start" % r)
        # Mean curvature of the fitted sphere times a: a / r_m = 1 / r within the quadratic fit's
        # error at level 2 (above 1: the markers sit inside a).
        check(abs(fields["mean_curvature"].mean() - 1.0 / r) < 0.05 / r, "mean curvature x a near a / r_m at kt %g" % kt)
        if kt == 0.0:
            check(abs(fields["stretch_1"] - 1).max() < 1e-9 and abs(fields["stretch_2"] - 1).max() < 1e-9,
                  "no stretch at the start")
            check(abs(fields["turned_angle"]).max() < 1e-12, "no turn at the start")
        else:
            check(fields["stretch_1"].max() > 1.001 and fields["stretch_2"].min() < 0.999, "stretched at kt %g" % kt)
            check(abs(fields["membrane_velocity"]).max() > 0.01, "the membrane moves at kt %g" % kt)
            check((fields["stretch_1"] >= fields["stretch_2"] - 1e-12).all(), "stretch_1 >= stretch_2")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
