#!/usr/bin/env python3
"""examples/tidal_shear -var original 1 runs the model as the original program did.

A short run of the preset (2 time-series rows, 2,340 steps). Required: it starts from the
shipped original bed (consolidated_original_0.data) with the original's integrator and
pressure iteration; its fluid cell height, mu_f and plate mass are those that keep the
reduced case's groups for that bed's own H and phi (groups.py bed_parameters, to the 4
digits in.params gives them); the bed starts at the original run's coordination, 4.58, within
0.1 (the bed was prepared for it: 4.53; shared/spec/original_run_contacts.txt's first row);
the relaxed iteration ran (sweeps > 0) and every value is finite.

Usage: check_tidal_shear_original.py --lmp LMP --plugin-dir DIR
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "tidal_shear")
sys.path.insert(0, EXAMPLE)
from groups import bed_geometry, bed_parameters    # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--plugin-dir", required=True)
    args = ap.parse_args()
    work = tempfile.mkdtemp()
    try:
        for name in os.listdir(EXAMPLE):
            if name.startswith("in.") or name.endswith(".data"):
                shutil.copy(os.path.join(EXAMPLE, name), work)
        env = dict(os.environ, OMP_NUM_THREADS="1",
                   LD_LIBRARY_PATH=args.plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
        subprocess.run([args.lmp, "-in", "in.tidal_shear", "-var", "original", "1", "-var",
                        "run_steps", "2340", "-log", "log.original", "-screen", "none"],
                       cwd=work, env=env, check=True)
        params = {}
        for line in open(os.path.join(work, "checkpoint_params.txt")):
            v = line.split()
            if len(v) == 4 and v[0] == "variable":
                params[v[1][3:]] = v[3]
        log = open(os.path.join(work, "log.original")).read()
        rows = [[float(x) for x in l.split()] for l in open(os.path.join(work, "timeseries.txt"))
                if not l.startswith("#")]
        names = open(os.path.join(work, "timeseries.txt")).readline().lstrip("# ").split()
        col = {n: k for k, n in enumerate(names)}
        height, phi = bed_geometry(os.path.join(EXAMPLE, "consolidated_original_0.data"))
        expected = bed_parameters(height, phi)
        ok = True

        def check(cond, what):
            nonlocal ok
            print(("ok    " if cond else "FAIL  ") + what)
            ok &= bool(cond)
        check("read_data consolidated_original_0.data" in log, "starts from the shipped original bed")
        check(params.get("integrator") == "nve/sphere/ty3", "integrator %s" % params.get("integrator"))
        check(params.get("solver") == "relaxed", "solver %s" % params.get("solver"))
        for key, value in expected.items():
            got = float(params[key])
            check(abs(got / value - 1) < 5e-4, "%s %s keeps the groups for H %.4f, phi %.4f (%.6g)"
                  % (key, params[key], height, phi, value))
        z0 = rows[0][col["coordination"]]
        check(abs(z0 - 4.58) < 0.1, "starts at coordination %.3f (the original: 4.58)" % z0)
        check(len(rows) == 2 and all(math.isfinite(x) for r in rows for x in r), "2 finite rows")
        check(all(r[col["solver_iters"]] > 0 for r in rows), "relaxed sweeps %s" % (
            [r[col["solver_iters"]] for r in rows]))
        return 0 if ok else 1
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
