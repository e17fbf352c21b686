"""What the studies of bench/ share, and nothing else: running lmp on examples/tidal_shear
(runs), the beds and scenes the runs start from (beds), the ensembles of runs that differ by
round-off and their bands (ensembles). A study imports this package, never another study;
the estimators themselves live in analysis/porewater_analysis, which importing this package
puts on the path.

A study script finds it with
    sys.path.insert(0, os.path.dirname(HERE))    # HERE: the study's folder
    from common import ...

PW_BENCH_SMOKE=DIR (bench/smoke.py sets it) is the short setting: every study then runs each
of its runs for a few thousand steps at most (each length it shortens reads short(value,
smoke_value)) and writes its pages and figures under DIR (out_dir), never over the
committed ones. Tables made from such runs say nothing."""
import os
import sys

COMMON = os.path.dirname(os.path.abspath(__file__))
BENCH = os.path.dirname(COMMON)
REPO = os.path.dirname(BENCH)
EXAMPLE = os.path.join(REPO, "examples", "tidal_shear")
sys.path.insert(0, os.path.join(REPO, "analysis"))

SMOKE = os.environ.get("PW_BENCH_SMOKE") or None


def short(value, smoke_value):
    """value, or smoke_value under the short setting (PW_BENCH_SMOKE)"""
    return smoke_value if SMOKE else value


def out_dir(study_dir):
    """where a study writes its pages and figures: its own folder, or DIR/<study> under the
    short setting"""
    if not SMOKE:
        return study_dir
    d = os.path.join(SMOKE, os.path.basename(study_dir))
    os.makedirs(d, exist_ok=True)
    return d
