#!/usr/bin/env python3
"""examples/tidal_shear killed and continued equals the uninterrupted run, bit for bit.

A short run of the example (fluid, plate, shear layer, every output) in chunks of
`checkpoint`, uninterrupted; then the same run killed with SIGKILL (the whole process group,
as a batch queue does) at a random moment after its first checkpoint, once per seed, and
continued with `-var continue 1`. Required, for each seed: the time series rows (comment
lines apart: a continued file says where it was continued), the profile file and the final
checkpoint (every grain's state, the contacts' springs, every fix's state, the clock) equal
byte for byte (with /kk: but for the capacity the KOKKOS contact history declares, which
follows the largest partner count the process has seen), and the final state written by
write_data. The same for a run that ends on a profile block's step and is continued from
it. `--during-write`: the kill comes while a checkpoint is being written (the temporary file
exists, not yet renamed): the continuation must start from the checkpoint before it and
still end equal.

Usage: check_tidal_shear_continue.py --lmp LMP --plugin-dir DIR [--mode serial|np2|kk|kk_np2]
       [--mpirun MPIRUN] [--seeds N] [--during-write]
Exit 77 (skipped) for --mode kk or kk_np2 on a LAMMPS without KOKKOS (PW_HOST_KOKKOS=0).
"""
import argparse
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "tidal_shear")
# 12,000 steps in chunks of one row (120 steps, 10,000 rows per cycle): 100 checkpoints, two
# profile blocks (every 6,000 steps). Every row right after a run's setup: a count that missed
# the setup's new atom order (compute coordination/original on LAMMPS 29Sep2021 before it
# rebuilt its list) differs in the continued run on every other row from the kill on, and
# failed 2 of 3 seeds here
ROW_STEPS, CHUNK_STEPS = 120, 120
RUN_STEPS, PROFILE_STEPS = 12000, 6000    # a run that ends on a profile block is continued from it


def run_variables(steps=RUN_STEPS):
    return ["-var", "run_steps", str(steps), "-var", "samples", "10000", "-var", "checkpoint",
            "0.000257", "-var", "write_state", "final"]


RUN = run_variables()


def command(args, extra, run_vars=RUN):
    cmd = [args.lmp, "-in", "in.tidal_shear"] + run_vars + extra
    if args.mode in ("kk", "kk_np2"):
        cmd += ["-k", "on", "t", "1", "-sf", "kk"]
    if args.mode in ("np2", "kk_np2"):
        cmd = [args.mpirun, "--oversubscribe", "-np", "2"] + cmd
    return cmd


def fresh_dir(root, name):
    d = os.path.join(root, name)
    os.makedirs(d)
    for f in os.listdir(EXAMPLE):
        if f.startswith("in.") or f == "consolidated_0.data":
            shutil.copy(os.path.join(EXAMPLE, f), d)
    return d


def run(args, d, extra, log, run_vars=RUN):
    with open(os.path.join(d, log), "w") as out:
        p = subprocess.run(command(args, extra, run_vars), cwd=d, stdout=out, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        sys.exit(f"FAIL  {' '.join(command(args, extra, run_vars))} in {d} exited {p.returncode}; "
                 f"see {log}:\n" + open(os.path.join(d, log)).read()[-3000:])


def start(args, d, log):
    out = open(os.path.join(d, log), "w")
    return subprocess.Popen(command(args, []), cwd=d, stdout=out, stderr=subprocess.STDOUT,
                            start_new_session=True)


def kill(p):
    os.killpg(p.pid, signal.SIGKILL)
    p.wait()


def data_rows(path):
    return [line for line in open(path) if not line.startswith("#")]


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def compare(ref, d, what):
    ok = True
    rows, ref_rows = data_rows(os.path.join(d, "timeseries.txt")), data_rows(os.path.join(ref, "timeseries.txt"))
    same = rows == ref_rows
    print(("ok    " if same else "FAIL  ") + f"{what}: timeseries.txt {len(rows)} rows "
          f"(uninterrupted {len(ref_rows)}) equal byte for byte")
    ok &= same
    for f in ("profiles.txt", "checkpoint.restart", "final.data"):
        a, b = read_bytes(os.path.join(d, f)), read_bytes(os.path.join(ref, f))
        note = ""
        if f == "checkpoint.restart":
            a, b, note = without_history_capacity(a, b)
        same = a == b
        print(("ok    " if same else "FAIL  ") + f"{what}: {f} equal byte for byte{note}")
        ok &= same
    return ok


# The KOKKOS contact history's per-atom restart block declares its capacity (2 + 4 x the
# most partners its arrays hold), which grows in steps of 8 from 8 with the largest partner
# count the process has seen: a continued process may hold another capacity for the same
# springs. That one integer after the fix's style name is left out of the comparison.
HISTORY_KK = b"NEIGH_HISTORY/KK/"


def without_history_capacity(a, b):
    """a and b without the capacity integer that follows the KOKKOS history's style name
    where the two differ only there"""
    cut = []
    at = a.find(HISTORY_KK)
    while at >= 0:
        start = a.index(b"\0", at) + 1
        if b[at:start] == a[at:start] and a[start:start + 4] != b[start:start + 4]:
            cut.append(start)
        at = a.find(HISTORY_KK, start)
    for start in reversed(cut):
        a, b = a[:start] + a[start + 4:], b[:start] + b[start + 4:]
    return a, b, " but the KOKKOS history's declared capacity" if cut else ""


def continued_from(d, log):
    m = re.search(r"continue: from checkpoint.restart at step (\d+)", open(os.path.join(d, log)).read())
    return int(m.group(1)) if m else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--plugin-dir", required=True)
    ap.add_argument("--mode", default="serial", choices=["serial", "np2", "kk", "kk_np2"])
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--during-write", action="store_true")
    args = ap.parse_args()
    if args.mode in ("kk", "kk_np2") and os.environ.get("PW_HOST_KOKKOS", "1") == "0":
        print("skipped: this LAMMPS has no KOKKOS package")
        return 77
    os.environ["LD_LIBRARY_PATH"] = args.plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", "")
    os.environ.update(OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMPI_ALLOW_RUN_AS_ROOT="1",
                      OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    root = tempfile.mkdtemp(prefix="pw_continue_")
    ok = True
    try:
        ref = fresh_dir(root, "uninterrupted")
        began = time.time()
        run(args, ref, [], "log.screen")
        duration = time.time() - began
        print(f"uninterrupted: {duration:.1f} s, {len(data_rows(os.path.join(ref, 'timeseries.txt')))} rows")
        if not args.during_write:
            # the restart's step is a profile block's (the grains' mean velocity is not in the
            # restart file: the continued run must keep the block, not write it again)
            name = "at a profile block"
            d = fresh_dir(root, "profile_block")
            run(args, d, [], "log.first", run_variables(PROFILE_STEPS))
            run(args, d, ["-var", "continue", "1"], "log.continued")
            print(f"{name}: ran to step {PROFILE_STEPS}; continued from step "
                  f"{continued_from(d, 'log.continued')}")
            ok &= compare(ref, d, name)
        cases = [("during-write", None)] if args.during_write else \
            [(f"seed {s}", random.Random(s)) for s in range(1, args.seeds + 1)]
        for name, rng in cases:
            d = fresh_dir(root, name.replace(" ", "_"))
            ckpt, tmp = os.path.join(d, "checkpoint.restart"), os.path.join(d, "checkpoint.restart.tmp")
            for attempt in range(4):
                p = start(args, d, "log.killed")
                while not os.path.exists(ckpt) and p.poll() is None:
                    time.sleep(0.001)
                if rng is None:
                    # the next write after the first checkpoint: stop the run while its
                    # temporary file exists, make sure it still does, then kill
                    while p.poll() is None and not os.path.exists(tmp):
                        pass
                    if p.poll() is None:
                        os.killpg(p.pid, signal.SIGSTOP)
                    caught = p.poll() is None and os.path.exists(tmp)
                    size = os.path.getsize(tmp) if caught else 0
                    if p.poll() is None:
                        kill(p)
                    detail = f"killed with checkpoint.restart.tmp at {size} bytes"
                else:
                    time.sleep(rng.uniform(0.0, 0.6) * duration)
                    caught = p.poll() is None
                    if caught:
                        kill(p)
                    detail = "killed"
                if caught:
                    break
                print(f"note  {name}: the run ended before the kill (attempt {attempt + 1}); again")
                shutil.rmtree(d)
                d = fresh_dir(root, name.replace(" ", "_"))
                ckpt, tmp = os.path.join(d, "checkpoint.restart"), os.path.join(d, "checkpoint.restart.tmp")
            else:
                print(f"FAIL  {name}: could not kill the run before it ended")
                ok = False
                continue
            rows_at_kill = len(data_rows(os.path.join(d, "timeseries.txt")))
            run(args, d, ["-var", "continue", "1"], "log.continued")
            step = continued_from(d, "log.continued")
            print(f"{name}: {detail} after {rows_at_kill} rows; continued from step {step}")
            if rng is None:
                # the write in progress is the checkpoint at the last row's step (a chunk's rows
                # are printed before its checkpoint): the one before it is used. Usually the
                # second write (step 120 used); on a loaded machine the wait for the temporary
                # file can miss a write and catch a later one
                expected = ROW_STEPS * rows_at_kill - CHUNK_STEPS
                good = step == expected and expected >= CHUNK_STEPS
                print(("ok    " if good else "FAIL  ") + f"{name}: continued from the checkpoint "
                      f"before the one being written (step {step}, expected {expected})")
                ok &= good
            ok &= compare(ref, d, name)
    finally:
        if ok:
            shutil.rmtree(root, ignore_errors=True)
        else:
            print(f"work folder kept: {root}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
