"""Wall time of every scene of run.sh before and after the performance work:
the committed whole run each scene had before it (2026-11-22 .. 12-01,
where one exists), the defaults of 2a1bd1b (2026-12-02) and the current
defaults (runs/<scene>/2a1bd1b and runs/<scene>/default). Writes
wall_times.png. The machine's speed varied between the days (README)."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from runs_io import wall_time  # noqa: E402

root = os.path.join(here, "..")
# The runs before the performance work: scene -> (screen.txt, MPI ranks).
before = {
    "two_bodies": ("contact/two_bodies/runs/consistent/screen.txt", 2),
    "sent_coarse": ("phase_field/sent_scene/runs/screen.txt", 2),
    "ductile_notch": ("plasticity/ductile_notch/runs/h0.05-delta1e-3/screen.txt",
                      2),
    "hertz_sphere": ("contact/hertz_sphere/runs/2026-11-al-amg/h4-w0.2/screen.txt", 2),
    "ironing": ("contact/ironing/runs/screen.txt", 1),
}
scenes = ["two_bodies", "block_on_plate", "sent_coarse", "ductile_notch",
          "hertz_sphere", "ironing", "necking_bar", "box_compression"]
series = [("before the performance work (2026-11-22 .. 12-01)", None),
          ("defaults of 2a1bd1b (2026-12-02)", "2a1bd1b"),
          ("current defaults", "default")]


def seconds(scene, variant):
    if variant is None:
        if scene not in before:
            return None
        return wall_time(os.path.join(root, before[scene][0]))
    path = os.path.join(here, "runs", scene, variant, "screen.txt")
    return wall_time(path) if os.path.exists(path) else None


try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("matplotlib missing (scripts/install-deps.sh --plots): no plot")

fig, ax = plt.subplots(figsize=(9, 4.8))
width = 0.27
for k, (label, variant) in enumerate(series):
    xs, ys = [], []
    for i, scene in enumerate(scenes):
        t = seconds(scene, variant)
        if t is not None:
            xs.append(i + (k - 1) * width)
            ys.append(t)
    bars = ax.bar(xs, ys, width, label=label)
    for x, y in zip(xs, ys):
        ax.text(x, y * 1.05, f"{y:.0f}", ha="center", va="bottom", fontsize=7)
ax.set_yscale("log")
ax.set_xticks(range(len(scenes)))
ax.set_xticklabels([s + (" (1 rank before)" if before.get(s, ("", 2))[1] == 1
                         else "") for s in scenes], rotation=20, fontsize=8)
ax.set_ylabel("wall time of the whole scene, 2 MPI ranks [s]")
ax.set_title("Shipped scenes before and after the performance work")
ax.grid(True, axis="y", which="both", lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(here, "wall_times.png"), dpi=120)
print("wrote", os.path.join(here, "wall_times.png"))
