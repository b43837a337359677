"""Readers shared by the benchmark reports: a run's `statistics` table, the
wall time its screen output ends with, and the sections of its timer
table."""
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


def find(pattern, text, default=None):
    """The first group of @p pattern in @p text, or @p default."""
    m = re.search(pattern, text)
    return m.group(1) if m else default


def timer_section(screen, name):
    """Wall time [s] of the timer section @p name of a run's screen output
    (0 if absent)."""
    value = find(r"\| " + re.escape(name) + r"\s*\|\s*\d+\s*\|\s*([\d.e+-]+)s",
                 screen)
    return float(value) if value else 0.
