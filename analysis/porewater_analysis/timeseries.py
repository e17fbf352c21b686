"""A run folder of examples/tidal_shear: its time series and the parameters it started with."""
import lzma
import os

import numpy as np


def load(path):
    """{column: array} of a time series: the first line `# name name ...`, rows of numbers;
    later lines starting with '#' (a continued run's `# continued from checkpoint.restart`)
    are comments, which np.loadtxt skips. Where `path` is missing, `path`.xz (a time series
    kept compressed, as the repository keeps Table S1's)"""
    if not os.path.exists(path) and os.path.exists(path + ".xz"):
        path += ".xz"
    with (lzma.open(path, "rt") if path.endswith(".xz") else open(path)) as f:
        names = f.readline().lstrip("# ").split()
        data = np.loadtxt(f, ndmin=2)
    if data.size == 0:             # the header alone: a run stopped before its first row
        data = np.empty((0, len(names)))
    return {n: data[:, k] for k, n in enumerate(names)}


def complete(path, t_end):
    """whether the time series at path reaches t_end (to 0.01 s)"""
    try:
        return load(path)["time"][-1] >= t_end - 0.01
    except (OSError, ValueError, IndexError):
        return False


def nearest_rows(time, at):
    """the index of the row of `time` (ascending) nearest each time in `at`"""
    at = np.asarray(at, dtype=float)
    after = np.searchsorted(time, at).clip(1, len(time) - 1)
    return np.where(time[after] - at < at - time[after - 1], after, after - 1)


def whole_cycles(t, period):
    """the forcing cycles a time series covers from t = 0 (to complete()'s 0.01 s)"""
    return int(np.floor((t[-1] + 0.01) / period))


def run_parameters(run_dir):
    """{name: value} of run_dir/checkpoint_params.txt, which in.checkpoint_params writes at the
    start of a run (lines `variable ck_NAME index VALUE`); numbers as floats, words as text"""
    params = {}
    with open(os.path.join(run_dir, "checkpoint_params.txt")) as f:
        lines = f.readlines()
    for line in lines:
        fields = line.split()
        if len(fields) == 4 and fields[0] == "variable" and fields[1].startswith("ck_"):
            try:
                params[fields[1][3:]] = float(fields[3])
            except ValueError:
                params[fields[1][3:]] = fields[3]
    return params
