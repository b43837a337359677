#!/usr/bin/env python3
"""Builds results.md and sent.png (l_f = 0.05 mm), or results_lf<L>.md and
sent_lf<L>.png (other l_f): the table and the peak-force error against wall
time, from runs/lf<L>/*/statistics of benchmarks/phase_field/sent/run.sh.
Usage: report.py DIR LF_MM"""
import glob
import os
import re
import sys

here = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from runs_io import read_statistics  # noqa: E402

lf_mm = sys.argv[2] if len(sys.argv) > 2 else "0.05"
root = os.path.join(here, "runs", "lf" + lf_mm)
suffix = "" if lf_mm == "0.05" else "_lf" + lf_mm
results_md = os.path.join(here, f"results{suffix}.md")
plot_png = os.path.join(here, f"sent{suffix}.png")


def load(run):
    rows = read_statistics(os.path.join(run, "statistics"))
    screen = open(os.path.join(run, "screen.txt")).read()
    m = re.match(r"q(\d)-h(\d+)-(\w+)-([\w-]+?)-dt([\d.]+)(?:-box(\d+))?$", os.path.basename(run))
    mesh = re.search(r"File name = .*_h([\d.e-]+)_b", open(os.path.join(run, "scene.prm")).read())
    thickness_mm = float(mesh.group(1))  # the slab is one element (h) thick
    # force per unit thickness [kN/mm] = F [N] / (t [mm]) / 1000
    force = [r["F2_y"] / thickness_mm / 1e3 for r in rows]
    disp = [r["u2_y"] * 1e3 for r in rows]  # mm
    k = max(range(len(force)), key=lambda i: force[i]) if force else 0
    # The peak is known once a later step shows the force falling, or when
    # the run ended at a limit point: the load step was halved below the
    # minimum without convergence. Then the limit point lies between the
    # last converged load and the smallest failed one after it, and a force
    # still rising there is bracketed by extrapolating the last slope.
    times = [r["time"] for r in rows]
    limit = None
    if "would have to be smaller than 'Load stepping/Minimum time step'" in screen and len(rows) > 2:
        failed = [float(t) for t in re.findall(r"step at t = ([\d.e+-]+) failed", screen)]
        above = [t for t in failed if t > times[-1]]
        if above:
            t_fail = min(above)
            slope = (force[-1] - force[-2]) / (times[-1] - times[-2])
            upper = force[-1] + max(slope, 0.) * (t_fail - times[-1]) if k == len(force) - 1 else force[k]
            limit = dict(t_last=times[-1], t_fail=t_fail, upper=upper)
    complete = k < len(force) - 1 or limit is not None
    # Cost of finding the peak: up to the step after it (the first step that
    # shows the force falling); what a run does after that (cut-backs at the
    # limit point, the crack running) is not part of the comparison.
    last = rows[min(k + 1, len(rows) - 1)] if rows else {}
    return dict(name=os.path.basename(run), degree=int(m.group(1)), ratio=int(m.group(2)),
                strategy=m.group(3), solver=m.group(4), dt=float(m.group(5)),
                box=int(m.group(6)) if m.group(6) else None,
                dofs=int(re.search(r"DoFs: (\d+)", screen).group(1)),
                peak=force[k] if force else float("nan"), u_peak=disp[k] if disp else float("nan"),
                newton=int(sum(r["newton_iterations"] for r in rows[:k + 2])),
                stag=int(sum(r.get("staggered_iterations", 0) for r in rows[:k + 2])),
                linear=int(sum(r["linear_iterations"] for r in rows[:k + 2])),
                cutbacks=int(sum(r["cutbacks"] for r in rows[:k + 2])),
                steps=min(k + 2, len(rows)) - 1, assembly=last.get("assembly_time", 0.),
                solve=last.get("solve_time", 0.), wall=last.get("wall_time", 0.),
                complete=complete, limit=limit, force=force, disp=disp)


runs = [load(r) for r in sorted(glob.glob(os.path.join(root, "q*")))
        if os.path.exists(os.path.join(r, "statistics"))]
ref_candidates = [r for r in runs if r["complete"]]
ref = max(ref_candidates, key=lambda r: (r["degree"] * r["ratio"], r["degree"], -r["dt"]))
for r in runs:
    r["error"] = abs(r["peak"] - ref["peak"]) / ref["peak"]

out = open(results_md, "w")
out.write(f"SENT slab, l_f = {lf_mm} mm; reference: {ref['name']} "
          f"(F_max = {ref['peak']:.5f} kN/mm at u = {ref['u_peak']:.4g} mm, {ref['dofs']} DoFs)\n\n")
out.write("Counts and times up to the step after the peak (or to the limit point). Limit point: "
          "the run stopped there (the load step halved below its minimum); t from the last "
          "converged to the first failed load, and the force bracket (F_max and the last "
          "slope extrapolated to the failed load, where the force was still rising).\n\n")
out.write("| run | DoFs | F_max kN/mm | u at F_max mm | error vs ref | limit point t | F_max bracket kN/mm "
          "| steps | Newton its | alternations | linear its / Newton | cut-backs | assembly s | solve s "
          "| wall s |\n")
out.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
for r in sorted(runs, key=lambda r: (r["dt"], r["degree"], r["ratio"], r["strategy"], r["solver"])):
    flag = "" if r["complete"] else " (incomplete)"
    lim = r["limit"]
    lim_t = f"[{lim['t_last']:.6g}, {lim['t_fail']:.6g}]" if lim else "-"
    lim_f = f"[{r['peak']:.5f}, {lim['upper']:.5f}]" if lim else "-"
    out.write(f"| {r['name']}{flag} | {r['dofs']} | {r['peak']:.5f} | {r['u_peak']:.4g} | "
              f"{r['error']:.2e} | {lim_t} | {lim_f} | "
              f"{r['steps']} | {r['newton']} | "
              f"{r['stag'] if r['strategy'].startswith('staggered') else '-'} | "
              f"{r['linear'] / max(r['newton'], 1):.1f} | "
              f"{r['cutbacks']} | {r['assembly']:.1f} | {r['solve']:.1f} | {r['wall']:.1f} |\n")
out.close()
print(open(results_md).read())

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib missing (scripts/install-deps.sh --plots): no plot")
    sys.exit(0)

fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.8))
methods = sorted({(r["strategy"], r["solver"]) for r in runs})
markers = {2: "o", 3: "s"}
for strategy, solver in methods:
    for degree in (2, 3):
        pts = sorted([(r["wall"], r["error"]) for r in runs
                      if r["strategy"] == strategy and r["solver"] == solver
                      and r["degree"] == degree and r is not ref and r["complete"]
                      and (r["dt"] == 0.02 or lf_mm != "0.05")])
        if pts:
            a.loglog(*zip(*pts), marker=markers[degree], label=f"Q{degree} {strategy} {solver}")
a.set_xlabel("wall time [s]")
a.set_ylabel("relative error of F_max")
a.set_title(f"SENT peak force, l_f = {lf_mm} mm" + (", dt = 0.02" if lf_mm == "0.05" else ""))
a.grid(True, which="both", alpha=0.3)
a.legend(fontsize=7)
for r in sorted(runs, key=lambda r: r["dofs"]):
    # l_f = 0.05 mm: the GMRES runs (the others lie on them); other l_f:
    # every monolithic run, near the peak
    if r["strategy"] == "monolithic" and (r["solver"] == "gmres-amg" or lf_mm != "0.05"):
        b.plot(r["disp"], r["force"], marker="." if lf_mm != "0.05" else None,
               label=f"Q{r['degree']} h = l_f/{r['ratio']}, dt = {r['dt']}, {r['solver']}")
if lf_mm != "0.05":
    b.set_xlim(0.0038, 0.0048)
    b.set_ylim(0.5, 0.62)
b.set_xlabel("top displacement [mm]")
b.set_ylabel("force per thickness [kN/mm]")
b.set_title("force-displacement (monolithic)" + (", near the peak" if lf_mm != "0.05" else ""))
b.legend(fontsize=7)
b.grid(True, alpha=0.3)
fig.tight_layout()
fig.savefig(plot_png, dpi=120)
print("wrote", plot_png)
