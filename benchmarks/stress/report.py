#!/usr/bin/python3
"""The stress runs of run.sh: per case the exit code and what it means,
how far the run got (time reached against the end time), accepted steps,
cut-backs, Newton iterations, the wall time, the end state (force on the
block's top, max s, max alpha, the largest penetration), whether the
statistics or any field output hold a NaN or Inf, whether every file the
.pvd series names exists, and the run's last message. Writes results.md;
exits 1 when a run crashed, hung or wrote a non-finite number."""
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import read_statistics  # noqa: E402

cases = {
    "large_step": "load step 10x the scene's (6 mm)",
    "eta_f_zero": "eta_f = 0, plastic work driver, to 18 mm",
    "eta_p_small": "eta_p = 1 Pa s (paper 1e6), to 18 mm",
    "moduli_1e4": "block 1e4 times softer than the plate, to 18 mm",
    "friction_1": "mu_c = 1, to 18 mm",
    "friction_10": "mu_c = 10, to 18 mm",
    "lf_h": "l_f = l_p = h (32.5 mm), plastic work driver, to 18 mm",
    "lf_quarter_h": "l_f = l_p = h/4 (8.1 mm, warned), plastic work driver, to 18 mm",
    "invert": "plate on a rigid support, block pressed 45 mm (its height: 40 mm)",
    "crack_in_contact": "block beside the clamp, plastic work driver (w_c = 1e5), to 30 mm",
}
meaning = {0: "end reached", 1: "bad input", 2: "gave up cleanly",
           3: "stopped by SIGTERM", 124: "time limit (hang?)"}


def non_finite_in_fields(run):
    """Names of point/cell arrays with NaN or Inf in any .pvtu of the run
    (None if vtk is missing or there is no output)."""
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        return None
    files = sorted(f for f in os.listdir(run) if f.endswith(".pvtu"))
    if not files:
        return None
    bad = set()
    for name in files:
        reader = vtk.vtkXMLPUnstructuredGridReader()
        reader.SetFileName(os.path.join(run, name))
        reader.Update()
        grid = reader.GetOutput()
        for data in (grid.GetPointData(), grid.GetCellData()):
            for i in range(data.GetNumberOfArrays()):
                values = vtk_to_numpy(data.GetArray(i))
                if not numpy.isfinite(values).all():
                    bad.add(data.GetArrayName(i))
    return sorted(bad)


def series_complete(run):
    """True when every file listed in the .pvd series exists."""
    pvd = os.path.join(run, "solution.pvd")
    if not os.path.isfile(pvd):
        return False
    for ds in ET.parse(pvd).getroot().iter("DataSet"):
        if not os.path.isfile(os.path.join(run, ds.get("file"))):
            return False
    return True


def last_message(screen):
    """The run's last error or stop message ("" when it ended normally)."""
    for line in reversed(screen.split("\n")):
        if re.match(r"\s*(Error|Stopped)", line):
            return line.strip()[:200]
    return ""


rows, failures = [], []
for case, what in cases.items():
    run = os.path.join(here, "runs", case)
    if not os.path.isfile(os.path.join(run, "exit_code")):
        continue
    code = int(open(os.path.join(run, "exit_code")).read())
    wall = int(open(os.path.join(run, "wall_time_ms")).read()) / 1000
    screen = open(os.path.join(run, "screen.txt"), errors="replace").read()
    end = float(re.search(r"set End time\s*=\s*(\S+)",
                          open(os.path.join(run, "scene.prm")).read().split(
                              "subsection Load stepping")[-1]).group(1))
    stats_path = os.path.join(run, "statistics")
    text = open(stats_path).read() if os.path.isfile(stats_path) else ""
    stats_finite = not re.search(r"nan|inf", text, re.I)
    stats = read_statistics(stats_path) if text else []
    last = stats[-1] if stats else {}
    fields = non_finite_in_fields(run)
    complete = series_complete(run)
    ok = (code in (0, 2) and stats_finite and fields == [] and complete)
    if not ok:
        failures.append(case)
    rows.append(
        "| `%s` | %s | %d (%s) | %.4g / %.4g | %d | %d | %d | %.0f | %.4g | %.3g | %.3g | %.3g | %s | %s | %s | %s |"
        % (case, what, code, meaning.get(code, "crash"), last.get("time", 0), end,
           len(stats) - 1 if stats else 0,
           sum(r.get("cutbacks", 0) for r in stats),
           sum(r.get("newton_iterations", 0) for r in stats), wall,
           -last.get("F2_z", 0) / 1e3, last.get("max_s", 0),
           last.get("max_alpha", 0), last.get("contact1_max_penetration", 0),
           "yes" if stats_finite else "**no**",
           "yes" if fields == [] else ("?" if fields is None else "**no: %s**" % ", ".join(fields)),
           "yes" if complete else "**no**",
           last_message(screen).replace("|", "/")))

with open(os.path.join(here, "results.md"), "w") as out:
    out.write("# Stress runs (benchmarks/stress/run.sh)\n\n")
    out.write("| case | what | exit code | t reached / end | steps | cut-backs | "
              "Newton its | wall [s] | top force [kN] | max s | max alpha | "
              "max penetration [m] | statistics finite | fields finite | "
              "series complete | last message |\n")
    out.write("|" + "---|" * 16 + "\n")
    out.write("\n".join(rows) + "\n\n")
    out.write("A run passes when it ends with exit code 0 (end reached) or 2 "
              "(gave up cleanly), its statistics and all its field output "
              "hold no NaN or Inf, and every file its .pvd series names "
              "exists. Failing: %s.\n" % (", ".join(failures) or "none"))
print(open(os.path.join(here, "results.md")).read())
sys.exit(1 if failures else 0)
