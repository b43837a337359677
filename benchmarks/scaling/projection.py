#!/usr/bin/env python3
"""The time per Newton iteration of the 3-D elastic contact scene (two_bodies,
gmres-amg) projected from 2 to 1024 ranks with a latency-bandwidth model
whose every input is a measurement of this machine, and the network
constants of this machine against those of a cluster.

T(P) = compute + n_coll * a_coll(P) + m(P) * a + B(P) * b, per Newton
iteration, with
- compute = w(N) * N / P: w(N) the core-time per unknown measured on 2 ranks
  (../iterative_solver: 77, 87, 127 us per unknown at 138k, 444k, 1.03M),
  fitted as w = w0 (N / 1.03M)^g: the Krylov iterations grow (66, 77, 107)
  and so does w; the fit is extrapolated past 1.03M;
- n_coll collectives of a_coll(P) = a_ar * log2(P) each (a tree), n_coll
  from traffic/ (1726 at 138k on 2 ranks, 1530 at 19.8k), grown with the
  Krylov iterations (n_coll = c0 + c1 * Krylov iterations, fitted on the
  two sizes);
- m(P) point-to-point messages per rank: traffic/ gives ~600 per neighbour
  (573 on 2 ranks, 1 neighbour; 1809 on 4 ranks, 3 neighbours), the
  neighbours of a 3-D subdomain taken as min(P - 1, 26), grown with the
  Krylov iterations;
- B(P) bytes per rank: the halo of a subdomain, 26.5 MB on 2 ranks at 138k
  (one interface of 69k unknowns per rank), scaled with the subdomain's
  surface (N/P)^(2/3) and the number of its faces min(P - 1, 6);
- a, b, a_ar: network/results.md (this machine, shared memory) or a
  cluster's (InfiniBand: a = 1.5 us, b = 1 / 12 GB/s, a_ar = 2 us per tree
  level; the typical order of published EDR/HDR figures, not measured here).
Writes projection.md and projection.png.
"""
import math
import pathlib
import re

here = pathlib.Path(__file__).parent

# Measured, 3-D two bodies with gmres-amg on 2 ranks (../iterative_solver/README.md):
# unknowns, seconds per Newton iteration, Krylov iterations per solve.
MEASURED = [(137970, 5.31, 66), (443688, 19.4, 77), (1030000, 65.4, 107)]
# traffic/results.md (gmres-amg, 2 ranks): unknowns, collectives per Newton
# iteration, Krylov iterations per solve of that run (iterative_solver r0, r1).
COLLECTIVES = [(19788, 1530, 46), (137970, 1726, 66)]
MESSAGES_PER_NEIGHBOUR = 600.0  # traffic/: 573 (2 ranks), 1809 / 3 (4 ranks)
HALO_BYTES_2 = 26.48e6  # traffic/: busiest rank, 2 ranks, 138k unknowns
HALO_UNKNOWNS_2 = 137970 / 2

CLUSTER = {"a": 1.5e-6, "b": 1 / 12e9, "a_ar": 2e-6}


def measured_network():
    """a, b (least squares of the ping-pong times) and a_ar of network/."""
    text = (here / "network" / "results.md").read_text()
    p2p = [(float(n), float(t)) for n, t in re.findall(r"^p2p (\d+) (\S+)", text, re.M)]
    ar = {int(n): float(t) for n, t in re.findall(r"^allreduce (\d+) (\S+)", text, re.M)}
    small = [t for n, t in p2p if n <= 512]
    large = [(n, t) for n, t in p2p if n >= 1 << 20]
    a = min(small)
    b = sum(t - a for n, t in large) / sum(n for n, _ in large)
    return {"a": a, "b": b, "a_ar": ar[8]}  # 2 ranks: one tree level


def fit_power(points):
    """w0, g of w = w0 (N / N_last)^g through the first and last point."""
    (n1, w1), (n2, w2) = points[0], points[-1]
    g = math.log(w2 / w1) / math.log(n2 / n1)
    return w2, g, n2


w_points = [(n, t * 2 / n) for n, t, _ in MEASURED]
w0, g, n_ref = fit_power(w_points)
k_points = [(n, k) for n, _, k in MEASURED]
k0, gk, _ = fit_power(k_points)
(_, c_a, k_a), (_, c_b, k_b) = COLLECTIVES
c1 = (c_b - c_a) / (k_b - k_a)
c0 = c_a - c1 * k_a


def krylov(n):
    return k0 * (n / n_ref) ** gk


def terms(n, p, net):
    """compute, collectives, messages, bytes [s] per Newton iteration."""
    compute = w0 * (n / n_ref) ** g * n / p
    growth = krylov(n) / krylov(137970)
    n_coll = c0 + c1 * krylov(n)
    coll = n_coll * net["a_ar"] * max(1.0, math.log2(p))
    neighbours = min(p - 1, 26)
    msgs = MESSAGES_PER_NEIGHBOUR * neighbours * growth * net["a"]
    faces = min(p - 1, 6)
    halo = HALO_BYTES_2 * faces * ((n / p) / HALO_UNKNOWNS_2) ** (2 / 3) * growth
    return compute, coll, msgs, halo * net["b"]


def table(title, cases, net):
    lines = [f"### {title}", "",
             "| ranks | unknowns | compute [s] | collectives [s] | messages [s] | bytes [s] "
             "| per Newton iteration [s] | communication share | µs·core per unknown |",
             "|---|---|---|---|---|---|---|---|---|"]
    rows = []
    for n, p in cases:
        c = terms(n, p, net)
        t = sum(c)
        rows.append((p, t))
        lines.append(f"| {p} | {n:.3g} | {c[0]:.3g} | {c[1]:.3g} | {c[2]:.3g} | {c[3]:.3g} | "
                     f"{t:.3g} | {(t - c[0]) / t:.1%} | {t * p / n * 1e6:.3g} |")
    return lines + [""], rows


ranks = [2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]
here_net = measured_network()
out = ["# Projection of the time per Newton iteration to 1024 ranks", "",
       "From `projection.py` (its docstring states the model): the 3-D two bodies (elastic "
       "frictional contact, Q2) with gmres-amg. Every input is measured here "
       "(`../iterative_solver`, `traffic/`, `network/`) except the cluster's network "
       "constants. A model, not a measurement: it keeps today's Krylov growth "
       f"(iterations ∝ N^{gk:.2f}, core-time per unknown ∝ N^{g:.2f}, fitted from 138k to "
       "1.03M unknowns) and extrapolates it.", "",
       f"Network constants: this machine (shared memory, network/results.md) a = "
       f"{here_net['a'] * 1e6:.2g} µs, 1/b = {1 / here_net['b'] / 1e9:.2g} GB/s, all-reduce "
       f"{here_net['a_ar'] * 1e6:.2g} µs; the cluster a = {CLUSTER['a'] * 1e6:.2g} µs, "
       f"1/b = {1 / CLUSTER['b'] / 1e9:.2g} GB/s, {CLUSTER['a_ar'] * 1e6:.2g} µs per tree level.",
       ""]
weak_cases = [(500000 * p, p) for p in ranks]
small_cases = [(50000 * p, p) for p in ranks]
strong_cases = [(10e6, p) for p in ranks if p >= 16]
series = {}
for name, net in (("cluster", CLUSTER),):
    lines, series["weak"] = table(f"Weak scaling, 500k unknowns per rank ({name})",
                                  weak_cases, net)
    out += lines
    lines, series["small"] = table(f"Weak scaling, 50k unknowns per rank ({name})",
                                   small_cases, net)
    out += lines
    lines, series["strong"] = table(f"Strong scaling, 10M unknowns ({name})", strong_cases, net)
    out += lines
lines, _ = table("The same weak scaling with this machine's constants (as if its shared "
                 "memory reached every rank)", weak_cases[:3], here_net)
out += lines
(here / "projection.md").write_text("\n".join(out) + "\n")
print("\n".join(out))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    raise SystemExit("matplotlib missing: no plot")
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
ax = axes[0]
for cases, style, label in ((weak_cases, "-", "500k per rank"),
                            (small_cases, "--", "50k per rank")):
    p_w = [p for _, p in cases]
    parts = list(zip(*[terms(n, p, CLUSTER) for n, p in cases]))
    for part, colour, name in zip(parts, ["C0", "C1", "C2", "C3"],
                                  ["compute", "collectives", "messages", "bytes"]):
        ax.loglog(p_w, part, style, color=colour, label=f"{name}, {label}")
ax.set_xscale("log", base=2)
ax.set_xlabel("ranks")
ax.set_ylabel("s per Newton iteration")
ax.set_title("weak scaling (cluster): the parts")
ax.legend(fontsize=6)
ax = axes[1]
p_s = [p for p, _ in series["strong"]]
t_s = [t for _, t in series["strong"]]
ideal = [t_s[0] * p_s[0] / p for p in p_s]
ax.loglog(p_s, t_s, "o-", label="model")
ax.loglog(p_s, ideal, "k--", label="ideal")
ax.set_xscale("log", base=2)
ax.set_xlabel("ranks")
ax.set_ylabel("s per Newton iteration")
ax.set_title("strong: 10M unknowns (cluster)")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(here / "projection.png", dpi=120)
