#!/usr/bin/env python3
"""Lists the committed runs that are older than the physics they ran.

A run is a folder under benchmarks/ with a 'statistics' file. Its commit is
the one recorded in its log.txt ('revision <hash>' in the program's header)
or, for runs written before the program recorded it, the last commit that
changed the statistics file. The physics is every file under
source/materials, source/phase_field, source/contact, source/assembly,
source/coupled (the bound, the coupled system) and source/discretisation
(the elements), and their headers under include/ductile_contact/, and
Newton's acceptance rules (source/solver/newton_solver.cc); a run is stale when a
commit that changed the physics, other than in comments, help texts or formatting, is newer than
the run's commit.

A commit that changed those files without changing what a run computes
unless the run uses the feature it adds (its code runs only when the
feature is on, and every ctest output of the runs without it stayed as it
was) is listed with its reason in benchmarks/neutral_commits and does not
count.

A commit whose change acts only on runs with a phase field (a crack
model) is listed there as '<hash> only fracture: <reason>': it counts for
the runs whose statistics have a phase-field column (fracture_energy,
max_s, crack_area) and not for the others.

A run that stays on purpose (a historical comparison) is listed in a file
'historical' in its folder or in one of its parents: one line of reason.
Those are listed apart.

Usage: scripts/stale_runs.py [--markdown] [--fail]
  --markdown  a table for benchmarks/README.md
  --fail      exit 1 if a run is stale and not marked historical
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
PHYSICS = [
    "source/materials", "source/phase_field", "source/contact", "source/assembly",
    "source/coupled", "source/discretisation", "source/solver/newton_solver.cc",
    "include/ductile_contact/materials", "include/ductile_contact/phase_field",
    "include/ductile_contact/contact", "include/ductile_contact/assembly",
    "include/ductile_contact/coupled", "include/ductile_contact/discretisation",
]


def git(*args):
    return subprocess.run(["git", *args], cwd=ROOT, check=True, capture_output=True,
                          text=True).stdout.strip()


def changes_code(h):
    """Whether commit h changed the code of the physics: its removed and added
    lines, comments and lines of help text dropped and white space removed,
    differ (a commit that changes comments or help texts or only reformats
    does not count)."""
    diff = git("show", "--format=", "--unified=0", h, "--", *PHYSICS)
    removed, added = [], []
    for line in diff.splitlines():
        if line.startswith(("+++", "---")) or not line.startswith(("+", "-")):
            continue
        text = line[1:].strip()
        # Comments and help texts (string literals) do not count.
        if text and not text.startswith(("//", "*", "/*")):
            code = re.sub(r'"(?:[^"\\]|\\.)*"', '""', text)
            (added if line[0] == "+" else removed).append("".join(code.split()))
    # Adjacent literals are one string in C++: a re-wrapped help text is too.
    def joined(lines):
        return re.sub(r'(?:"")+', '""', "".join(lines))

    return joined(removed) != joined(added)


PHASE_FIELD_COLUMNS = {"fracture_energy", "max_s", "crack_area"}


def neutral_commits():
    """The commits of benchmarks/neutral_commits: {full hash: scope}, the
    scope None (neutral for every run) or 'fracture' (acts only on runs
    with a phase field)."""
    path = ROOT / "benchmarks" / "neutral_commits"
    if not path.exists():
        return {}
    listed = {}
    for line in path.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        words = line.split()
        scope = None
        if len(words) > 2 and words[1] == "only":
            scope = words[2].rstrip(":")
            if scope != "fracture":
                sys.exit(f"benchmarks/neutral_commits: unknown scope '{scope}' "
                         f"in '{line}' (allowed: fracture)")
        listed[git("rev-parse", words[0])] = scope
    return listed


def physics_commits():
    """Commits that changed the physics (not only its comments), newest
    first, but those neutral for every run in benchmarks/neutral_commits:
    (hash, unix time, scope)."""
    out = git("log", "--format=%H %ct", "--", *PHYSICS)
    commits = [(h, int(t)) for h, t in (line.split() for line in out.splitlines())]
    neutral = neutral_commits()
    return [(h, t, neutral.get(h)) for h, t in commits
            if (h not in neutral or neutral[h] is not None) and changes_code(h)]


def has_phase_field(folder):
    """Whether the run's statistics have a phase-field column."""
    with open(folder / "statistics", errors="replace") as f:
        for line in f:
            if not line.startswith("#"):
                return bool(PHASE_FIELD_COLUMNS & set(line.split()))
    return True


def run_commit(folder):
    """The run's commit and how it is known."""
    log = folder / "log.txt"
    if log.exists():
        with open(log, errors="replace") as f:
            head = f.read(4000)
        m = re.search(r"revision ([0-9a-f]{7,40})", head)
        if m:
            return m.group(1), "log.txt"
    rel = (folder / "statistics").relative_to(ROOT)
    h = git("log", "-1", "--format=%H", "--", str(rel))
    return (h, "git") if h else (None, "uncommitted")


def commit_time(h):
    try:
        return int(git("show", "-s", "--format=%ct", h))
    except subprocess.CalledProcessError:
        return None


def historical_reason(folder):
    for d in [folder, *folder.parents]:
        if d == ROOT:
            break
        f = d / "historical"
        if f.exists():
            return f.read_text().strip().splitlines()[0]
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--fail", action="store_true")
    args = parser.parse_args()

    all_changes = physics_commits()
    latest_hash = all_changes[0][0]
    stale, historical = [], []
    for stats in sorted((ROOT / "benchmarks").rglob("statistics")):
        folder = stats.parent
        cracking = has_phase_field(folder)
        changes = [(h, ct) for h, ct, scope in all_changes
                   if scope is None or (scope == "fracture" and cracking)]
        h, source = run_commit(folder)
        t = commit_time(h) if h else None
        if t is not None and t >= changes[0][1]:
            continue
        newer = sum(1 for _, ct in changes if t is None or ct > t)
        row = (str(folder.relative_to(ROOT)), (h or "-")[:10], source, newer)
        reason = historical_reason(folder)
        (historical if reason else stale).append(row + (reason or "",))

    if args.markdown:
        # One row per study (benchmarks/<area>/<study>), with its runs counted.
        groups = {}
        for r in stale + historical:
            key = ("/".join(r[0].split("/")[:3]), r[4])
            g = groups.setdefault(key, [0, set()])
            g[0] += 1
            g[1].add(r[1])
        print(f"Runs older than the last change to the physics they ran (the last of "
              f"all: {latest_hash[:10]}), from `scripts/stale_runs.py --markdown`:\n")
        print("| study | runs | their commits | historical because |")
        print("|---|---|---|---|")
        for (study, reason), (n, commits) in sorted(groups.items()):
            shown = ", ".join(sorted(commits)[:3]) + (" …" if len(commits) > 3 else "")
            print(f"| {study} | {n} | {shown} | {reason or 'stale: to be rerun'} |")
    else:
        print(f"last physics change: {latest_hash[:10]}")
        for r in stale:
            print(f"stale: {r[0]} ({r[1]}, {r[2]}; {r[3]} physics commits since)")
        for r in historical:
            print(f"historical: {r[0]} ({r[1]}): {r[4]}")
        print(f"{len(stale)} stale, {len(historical)} historical")
    return 1 if args.fail and stale else 0


if __name__ == "__main__":
    sys.exit(main())
