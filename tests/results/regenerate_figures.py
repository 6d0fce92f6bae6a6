#!/usr/bin/env python3
"""Every shipped report's figures regenerate: the toolkit's script (analysis/report/plot_report.py;
reports keep no copy of it), run on the report's figures/figure_data.json, draws exactly the
figures the report ships (the same file names; pixels depend on matplotlib's
version, so they are not compared). Run by CTest (results_figures) with Debian's python3, which
has matplotlib (scripts/install-deps). Prints 'N passed, M failed'; exits 1 on any failure."""
import glob
import os
import subprocess
import sys
import tempfile

top = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
script = os.path.join(top, "analysis", "report", "plot_report.py")
python = "/usr/bin/python3"
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAILED:", what)


for figures in sorted(glob.glob(os.path.join(top, "results", "*", "report", "figures"))):
    name = os.path.relpath(figures, top)
    data = os.path.join(figures, "figure_data.json")
    if not os.path.exists(data):
        continue
    check(not os.path.exists(os.path.join(figures, "plot_report.py")), name + " ships a copy of the script")
    shipped = sorted(os.path.basename(p) for p in glob.glob(os.path.join(figures, "*.png")))
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([python, script, data, out], capture_output=True, text=True)
        check(run.returncode == 0, name + ": the script failed: " + run.stderr[-500:])
        drawn = sorted(os.path.basename(p) for p in glob.glob(os.path.join(out, "*.png")))
    check(drawn == shipped, name + ": ships %s, the script draws %s" %
          (sorted(set(shipped) - set(drawn)), sorted(set(drawn) - set(shipped))))
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
