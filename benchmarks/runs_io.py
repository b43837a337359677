"""Readers shared by the benchmark reports: a run's `statistics` table and
the wall time its screen output ends with."""
import re


def read_statistics(path):
    """Rows of a `statistics` file as dicts column name -> float."""
    lines = [l for l in open(path).read().split("\n") if l.strip()]
    names = lines[0].split()
    return [dict(zip(names, map(float, l.split()))) for l in lines[1:]]


def wall_time(screen_path):
    """Total wall time [s] from the timer table at the end of screen.txt,
    None if the run did not finish."""
    m = re.search(r"Total wallclock time elapsed since start\s*\|\s*([\d.e+-]+)s",
                  open(screen_path).read())
    return float(m.group(1)) if m else None
