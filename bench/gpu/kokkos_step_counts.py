#!/usr/bin/python3
"""What one ordinary step of examples/tidal_shear with -sf kk asks of KOKKOS, counted on the
host backend (-k on t 1): Kokkos dispatches (for, reduce, scan) and deep copies per kernel
name, and LAMMPS' atom syncs (AtomKokkos::sync/modified) per caller, space and mask; per
step as the difference of a 2,000- and a 1,000-step run (whole fluid intervals and time
series samples for the reduced example, the same per step at any size:
common.runs.dispatches_per_step). The profiling hook bench/common/kokkos_dispatches.cpp counts,
loaded as KOKKOS_PROFILE_LIBRARY and preloaded.

A host backend has one memory: no sync copies anything there. On a GPU build each
sync(Host, mask) after the device changed those arrays copies them down (and the device's
next sync copies them up again when the host marked them modified), and each reduction
into a host scalar waits for the device. A sync whose mask is 0 does nothing anywhere.

    source scripts/env.sh; /usr/bin/python3 bench/gpu/kokkos_step_counts.py --work DIR \\
        [--var NAME VALUE ...] [--label TEXT] [--markdown OUT.md]

`--fluid-step-check`: what a fluid step of fix darcy/pressure/kk (its deposit kernel to its
force kernel) asks of the host: the example with -var fast 1 for 300 steps (12 fluid
steps), its atom syncs during fluid steps by caller. A sync that brings atom arrays to the
host for a host-side evaluation (the fixes' sync_for_variables, called before their top,
ztop, bottom or stress variables are evaluated) copies them down on a GPU; the kernels' own
syncs are to their execution space (on this backend the host too). Fails unless the example as shipped (`variables global`)
makes none and the same run with `variables atoms` makes one per fluid step (the control:
the count can see them). ctest: lammps.kokkos_fluid_step_host_copies.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common.runs import KOKKOS_DISPATCHES, prepare    # noqa: E402

STEPS = (1000, 2000)
ALL_MASK = 0xffffffff


def build_hook(work):
    hook = os.path.join(work, "kokkos_dispatches.so")
    source = KOKKOS_DISPATCHES
    if not os.path.exists(hook) or os.path.getmtime(hook) < os.path.getmtime(source):
        subprocess.run(["g++", "-O2", "-shared", "-fPIC", "-o", hook, source, "-ldl"], check=True)
    return hook


def read_lines(path):
    """{key: count} of a hook file's 'COUNT KEY' lines (the first line of KCOUNT_OUT apart)"""
    rows = {}
    for line in open(path):
        count, _, key = line.rstrip("\n").partition(" ")
        if count.isdigit():
            rows[key] = rows.get(key, 0) + int(count)
    return rows


def read_totals(path):
    words = open(path).readline().split()
    return {words[i]: int(words[i + 1]) for i in range(0, len(words), 2)}


def count(work, variables, name):
    """per-step counts of the example with -var `variables` in work/name"""
    d = os.path.join(work, name)
    prepare(d)
    hook = build_hook(work)
    runs = []
    for steps in STEPS:
        kcount, ksync = (os.path.join(d, "%s_%d.txt" % (k, steps)) for k in ("kcount", "ksync"))
        env = dict(os.environ, KOKKOS_PROFILE_LIBRARY=hook, LD_PRELOAD=hook, KCOUNT_OUT=kcount,
                   KSYNC_OUT=ksync, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
        extra = [a for kv in variables.items() for a in ("-var", kv[0], str(kv[1]))]
        subprocess.run(["lmp", "-k", "on", "t", "1", "-sf", "kk", "-in", "in.tidal_shear",
                        "-var", "run_steps", str(steps), "-screen", "none", "-log",
                        "log_%d.lammps" % steps] + extra, cwd=d, env=env, check=True)
        runs.append(read_run(kcount, ksync))
    return per_step(runs, STEPS)


def read_run(kcount, ksync):
    """a run's hook files: (totals, per kernel, per atom sync) (no KSYNC_OUT file: none)"""
    return (read_totals(kcount), read_lines(kcount), read_lines(ksync) if os.path.exists(ksync) else {})


def per_step(runs, steps):
    """the counts per step: the difference of the runs of steps[0] and steps[1] steps"""
    span = float(steps[1] - steps[0])

    def difference(a, b):
        keys = set(a) | set(b)
        return {k: (b.get(k, 0) - a.get(k, 0)) / span for k in keys if b.get(k, 0) != a.get(k, 0)}

    totals = difference(runs[0][0], runs[1][0])
    return {"totals": totals, "kernels": difference(runs[0][1], runs[1][1]),
            "atom": difference(runs[0][2], runs[1][2]),
            "dispatches": sum(totals.get(k, 0) for k in ("for", "reduce", "scan"))}


def print_and_append(text, markdown):
    """the tables to the screen and, given a file, appended to it"""
    print(text)
    if markdown:
        with open(markdown, "a") as f:
            f.write(text + "\n")


def host_syncs(atom):
    """sync(Host, mask != 0) calls per step and those with every array (ALL_MASK)"""
    calls = whole = 0.0
    for key, n in atom.items():
        what, space, mask = key.split(" ")[:3]
        if what == "sync" and space == "Host" and int(mask, 16) != 0:
            calls += n
            whole += n if int(mask, 16) == ALL_MASK else 0.0
    return calls, whole


def markdown(label, c):
    t = c["totals"]
    syncs, whole = host_syncs(c["atom"])
    out = ["### %s" % label, "",
           "per step: %.2f dispatches (for %.2f, reduce %.2f, scan %.2f), %.2f deep copies, "
           "%.2f fences; atom syncs to the host with a mask: %.2f (of every array: %.2f)" % (
               c["dispatches"], t.get("for", 0), t.get("reduce", 0), t.get("scan", 0),
               t.get("deep_copy", 0), t.get("fence", 0), syncs, whole), "",
           "| per step | kernel |", "|---|---|"]
    out += ["| %.3f | %s |" % (n, k[:120]) for k, n in sorted(c["kernels"].items(), key=lambda kv: -kv[1])]
    out += ["", "| per step | AtomKokkos call (space, mask, caller) |", "|---|---|"]
    out += ["| %.3f | %s |" % (n, k[:140]) for k, n in sorted(c["atom"].items(), key=lambda kv: -kv[1])]
    return "\n".join(out) + "\n"


# the host-side evaluations that sync atom arrays to the host (the caller the hook sees may be
# the function that calls sync_for_variables, which ends in the sync)
HOST_READERS = ("sync_for_variables", "sync_for_nonfinite_check", "::boundary_values",
                "::stress_now")
FLUID_CHECK_STEPS, FLUID_EVERY = 300, 25    # -var fast 1: a fluid step every 25 steps


def fluid_step_host_syncs(work, name, edit=None):
    """{caller: calls} of the syncs to the host with a mask, during fluid steps, that
    host-side readers make, in a run of the example in work/name (`edit`: the input's text
    changed by it first)"""
    d = os.path.join(work, name)
    prepare(d)
    if edit:
        path = os.path.join(d, "in.tidal_shear")
        text = open(path).read()
        open(path, "w").write(edit(text))
    ksync = os.path.join(d, "ksync.txt")
    # after what is preloaded already (a sanitizer's runtime must come first)
    preload = ":".join(p for p in (os.environ.get("LD_PRELOAD", ""), build_hook(work)) if p)
    env = dict(os.environ, KOKKOS_PROFILE_LIBRARY=build_hook(work), LD_PRELOAD=preload,
               KCOUNT_OUT=os.path.join(d, "kcount.txt"), KSYNC_OUT=ksync, OMP_NUM_THREADS="1",
               OMP_PROC_BIND="false")
    subprocess.run(["lmp", "-k", "on", "t", "1", "-sf", "kk", "-in", "in.tidal_shear", "-var", "fast",
                    "1", "-var", "run_steps", str(FLUID_CHECK_STEPS), "-screen", "none", "-log",
                    "log.lammps"], cwd=d, env=env, check=True)
    found = {}
    for key, n in (read_lines(ksync) if os.path.exists(ksync) else {}).items():
        words = key.split(" ")
        if words[0] != "fluid" or words[1] != "sync" or words[2] != "Host" or int(words[3], 16) == 0:
            continue
        caller = " ".join(words[4:])
        if any(r in caller for r in HOST_READERS):
            found[caller] = found.get(caller, 0) + n
    return found


def fluid_step_check(work):
    shipped = fluid_step_host_syncs(work, "fluid_step_shipped")
    control = fluid_step_host_syncs(work, "fluid_step_atoms",
                                    lambda t: t.replace("variables global", "variables atoms"))
    fluid_steps = FLUID_CHECK_STEPS // FLUID_EVERY
    print("fluid steps: %d; host-side syncs of atom arrays during them: as shipped %s, with "
          "`variables atoms` %s" % (fluid_steps, shipped or "none", control or "none"))
    ok = not shipped and sum(control.values()) >= fluid_steps
    print("ok" if ok else "FAIL")
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--work", required=True)
    ap.add_argument("--fluid-step-check", action="store_true")
    ap.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    ap.add_argument("--label", default="")
    ap.add_argument("--markdown", help="append the tables to this file")
    args = ap.parse_args()
    if args.fluid_step_check:
        sys.exit(fluid_step_check(os.path.abspath(args.work)))
    variables = dict(args.var)
    name = "counts" + "".join("_%s_%s" % kv for kv in variables.items())
    c = count(os.path.abspath(args.work), variables, name)
    text = markdown(args.label or "reduced example, -sf kk, %s" % (
        " ".join("-var %s %s" % kv for kv in variables.items()) or "defaults"), c)
    print_and_append(text, args.markdown)


if __name__ == "__main__":
    main()
