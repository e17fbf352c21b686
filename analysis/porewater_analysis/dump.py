"""A LAMMPS custom dump (one snapshot), as the example's grains_STEP.dump and the benchmarks'
write_dump files hold it."""
import numpy as np


def read_dump(path):
    """(box lengths along x, y, z, {column: array}) of a custom dump's snapshot, the grains in
    the order of their ids"""
    with open(path) as f:
        lines = f.readlines()
    bounds = next(i for i, l in enumerate(lines) if l.startswith("ITEM: BOX BOUNDS"))
    box = np.array([[float(v) for v in lines[bounds + k].split()[:2]] for k in (1, 2, 3)])
    header = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    names = lines[header].split()[2:]
    data = np.loadtxt(lines[header + 1:], ndmin=2)
    data = data[np.argsort(data[:, names.index("id")], kind="stable")]
    return box[:, 1] - box[:, 0], {n: data[:, k] for k, n in enumerate(names)}


def box_bounds(path):
    """the (lo, hi) of the box along x, y, z of a custom dump's snapshot"""
    with open(path) as f:
        lines = f.readlines()
    bounds = next(i for i, l in enumerate(lines) if l.startswith("ITEM: BOX BOUNDS"))
    return np.array([[float(v) for v in lines[bounds + k].split()[:2]] for k in (1, 2, 3)])
