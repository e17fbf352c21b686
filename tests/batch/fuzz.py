#!/usr/bin/env python3
"""Keyword fuzz test of every style of the plugin, CPU or /kk.

From a small valid input per style, every keyword line of the style (pair_style and
pair_coeff, the fix commands) is mutated one change at a time: a token dropped, repeated,
swapped with its neighbour or another one, or replaced by a non-number, -1, 0, 1e308,
-1e308, nan, inf, -inf, an empty word, 2147483648, 100000000 or a number with trailing
junk; a stray word is appended. Each
mutant runs as its own lmp process, as a batch job would run it (stdin not a terminal,
stdout and stderr to files), under a time limit, and is classified:

  rejected   exited nonzero with an ERROR line in stdout and in log.lammps  (ok)
  accepted   exited 0, the run completed and every thermo value is finite  (ok)
  FAIL       died by a signal, timed out, exited nonzero without the ERROR line in both
             files, or exited 0 without completing or with a non-finite thermo value

The mutants are enumerated in a fixed order; --accel picks the CPU styles (cpu), their /kk
variants (kk) or both; a run takes a sample of PW_FUZZ_COUNT of them (default 120: about
half a minute on two cores), drawn with PW_FUZZ_SEED (default 1) in turn from each input;
PW_FUZZ_COUNT=all runs every mutant (about 1500 per accel: 7 minutes on two jobs). Exit
status 1 if any mutant failed; the failures are written, with the input line and the tail
of each output, to --failures. Exit status 77 (skipped) for --accel kk where
PW_HOST_KOKKOS=0 (a LAMMPS without KOKKOS).

  fuzz.py --lmp LMP --plugin-dir DIR [--accel cpu|kk|both] [--jobs 2] [--timeout 20]
          [--failures FILE] [--list]
"""
import argparse
import concurrent.futures
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

# ---------------------------------------------------------------------------- the inputs

# A bed of 48 grains of diameter 0.98 on a cubic lattice in a box periodic in x and y,
# bounded in z, under gravity; group bottom is the lowest layer, top the highest.
SCENE = """plugin load porewater.so
units lj
atom_style sphere
atom_modify map array
boundary p p f
newton off
comm_modify vel yes
region box block 0 4 0 4 0 6 units box
create_box 1 box
lattice sc 1.0 origin 0.5 0.5 0.5
region bed block 0 4 0 4 0 3 units box
create_atoms 1 region bed
set type 1 diameter 0.98
set type 1 density 1.9099
velocity all create 0.01 4928 loop geom
region low block INF INF INF INF INF 1 units box
group bottom region low
group mobile subtract all bottom
region high block INF INF INF INF 2 INF units box
group top region high
neighbor 0.2 bin
neigh_modify delay 0 every 1 check yes
timestep 0.001
variable ptop equal 0.1*sin(time)
variable sigma equal 5+sin(time)
fix grav mobile gravity 1.0 vector 0 0 -1
"""

PAIR = "pair_style linear/coulomb\npair_coeff * * 1.0e4 1.0e4 0.5\n"
NVE = "fix integrate mobile nve/sphere\n"
RUN = "thermo 10\nrun 60\n"

# style -> (input, its keyword lines: the lines marked '@' are mutated; the first `head`
# tokens of a line, the command and the names before the keywords, are kept)
STYLES = {
    "pair_linear_coulomb": (
        SCENE + "@pair_style linear/coulomb lever radius dissipation yes overlap_limit 0.5\n"
        "@pair_coeff * * 1.0e4 1.0e4 0.5\n" + NVE +
        "compute lc all pair linear/coulomb\n"
        "thermo_style custom step ke pe c_lc c_lc[1]\n" + RUN),
    "darcy_pressure": (
        SCENE + PAIR + NVE +
        "@fix fl all darcy/pressure grid 4 4 6 viscosity 1 compressibility 1 density 1 "
        "permeability 1 kmax 0.9 top v_ptop gravity 0 0 -1 porosity 0.1 0.9 tol 1e-10 "
        "maxiter 200 every 2 interpolate fluid\n"
        "thermo_style custom step ke f_fl[1] f_fl[2] f_fl[3] f_fl[4] f_fl[5]\n" + RUN),
    "darcy_pressure_b": (
        SCENE + PAIR + NVE +
        "@fix fl mobile darcy/pressure grid 2 2 5 viscosity 1 compressibility 1 density 1 "
        "permeability 1 bottom 0.5 ztop 4.5 initial 0.1 atol 1e-12 zhi 5 top noflow "
        "interpolate step profile 20 profile.txt append yes vtk 30 grid\n"
        "thermo_style custom step ke f_fl[1] f_fl[2] f_fl[3] f_fl[4] f_fl[6]\n" + RUN),
    "wall_stress": (
        SCENE + PAIR + NVE +
        "@fix wall all wall/stress z auto stress v_sigma mass 1 kn 1.0e4 damping 1\n"
        "thermo_style custom step ke f_wall f_wall[1] f_wall[2] f_wall[3] f_wall[4]\n" + RUN),
    "wall_stress_b": (
        SCENE + PAIR + NVE +
        "@fix wall all wall/stress z 3.2 stress 5 mass 1 kn 1.0e4\n"
        "thermo_style custom step ke f_wall f_wall[1] f_wall[2]\n" + RUN),
    "shear_stress": (
        SCENE + PAIR + NVE +
        "fix wall all wall/stress z auto stress 5 mass 1 kn 1.0e4 damping 1\n"
        "@fix plate top shear/stress tau 1 mass 1\n"
        "thermo_style custom step ke f_plate[1] f_plate[2] f_plate[3]\n" + RUN),
    "darcy_grain": (
        SCENE + PAIR + NVE +
        "fix fl all darcy/pressure grid 4 4 6 viscosity 1 compressibility 1 density 1 "
        "permeability 1 top v_ptop gravity 0 0 -1\n"
        "@compute dg all darcy/grain fl\n"
        "compute dgs all reduce sum c_dg[1] c_dg[2]\n"
        "thermo_style custom step ke c_dgs[1] c_dgs[2]\n" + RUN),
    "coordination_original": (
        SCENE + PAIR + NVE +
        "@compute zo all coordination/original fixed bottom\n"
        "thermo_style custom step ke c_zo\n" + RUN),
    "progress": (
        SCENE + PAIR + NVE +
        "@fix prog all progress end 60 period 2.5 walltime 01:00:00 safety 1.5\n"
        "thermo_style custom step ke f_prog[2] f_prog[3]\nthermo 10\n"
        "run 60 every 20 NULL\nprint \"stopped $(f_prog[1])\"\n"),
    "nve_sphere_ty3": (
        SCENE + PAIR + "@fix integrate mobile nve/sphere/ty3 corrector yes\n"
        "thermo_style custom step ke pe\n" + RUN),
}
HEAD = {"pair_style": 2, "pair_coeff": 1, "fix": 4, "compute": 4}

KOKKOS = ["-k", "on", "t", "1", "-sf", "kk", "-pk", "kokkos", "neigh", "half", "newton", "off"]

# 100000000: a valid int that makes a grid too large for the int cell index (and a huge
# count elsewhere); 2147483648: one past the largest int
REPLACEMENTS = ["abc", "-1", "0", "1e308", "-1e308", "nan", "inf", "-inf", '""', "2147483648",
                "100000000", "1.5x"]

# ---------------------------------------------------------------------------- mutants


def mutations(line):
    """(description, mutated line) of every single change of the line's keyword part."""
    tokens = line.split()
    head = HEAD[tokens[0]]
    out = []
    for i in range(head, len(tokens)):
        t = tokens[i]
        out.append((f"drop '{t}' (token {i})", tokens[:i] + tokens[i + 1:]))
        out.append((f"repeat '{t}' (token {i})", tokens[:i + 1] + tokens[i:]))
        if i + 1 < len(tokens):
            s = list(tokens)
            s[i], s[i + 1] = s[i + 1], s[i]
            out.append((f"swap tokens {i} and {i + 1}", s))
        for r in REPLACEMENTS:
            if r != t:
                out.append((f"token {i} '{t}' -> {r}", tokens[:i] + [r] + tokens[i + 1:]))
    # a swap of far-apart tokens (chosen from the line itself, so the list stays fixed)
    pick = random.Random(line)
    for _ in range(3):
        if len(tokens) - head >= 3:
            i, j = sorted(pick.sample(range(head, len(tokens)), 2))
            s = list(tokens)
            s[i], s[j] = s[j], s[i]
            out.append((f"swap tokens {i} and {j}", s))
    out.append(("append a stray word", tokens + ["extra"]))
    return [(d, " ".join(m)) for d, m in out if m != tokens]


def accelerations(accel):
    """The values of `kokkos` that --accel selects."""
    return {"cpu": (False,), "kk": (True,), "both": (False, True)}[accel]


def all_mutants(accel="both"):
    """[(style, kokkos, description, original line, mutated line, input)] in a fixed order."""
    result = []
    for kokkos in accelerations(accel):
        for style, text in STYLES.items():
            lines = text.splitlines()
            for n, line in enumerate(lines):
                if not line.startswith("@"):
                    continue
                original = line[1:]
                for desc, mutated in mutations(original):
                    body = lines[:n] + [mutated] + lines[n + 1:]
                    body = [l[1:] if l.startswith("@") else l for l in body]
                    result.append((style + ("/kk" if kokkos else ""), kokkos, desc, original,
                                   mutated, "\n".join(body) + "\n"))
    return result


def sample(mutants, count, seed):
    """count mutant indices, drawn in turn from each input (CPU and /kk apart), so that a
    small sample still covers every style."""
    rng = random.Random(seed)
    groups = {}
    for i, m in enumerate(mutants):
        groups.setdefault(m[0], []).append(i)
    for g in groups.values():
        rng.shuffle(g)
    chosen = []
    while len(chosen) < count:
        for g in groups.values():
            if g and len(chosen) < count:
                chosen.append(g.pop())
    return sorted(chosen)


def valid_inputs(accel="both"):
    for kokkos in accelerations(accel):
        for style, text in STYLES.items():
            body = "\n".join(l[1:] if l.startswith("@") else l for l in text.splitlines()) + "\n"
            yield (style + ("/kk" if kokkos else ""), kokkos, "the valid input", "", "", body)

# ---------------------------------------------------------------------------- running


def thermo_values(log):
    """Every value of the thermo tables of a log (the rows under each `Step` header: a step
    number and one word per column; messages a run prints between them are not rows); None
    if no run finished."""
    values, columns, finished = [], 0, False
    for line in log.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            columns = len(words)
            continue
        if line.startswith("Loop time"):
            columns, finished = 0, True
            continue
        if columns and len(words) == columns and words[0].isdigit():
            values.extend(words)
    return values if finished else None


def classify(rc, out, log):
    if rc == 124:
        return "FAIL", "timed out"
    if rc > 128:
        return "FAIL", f"died by signal {rc - 128}"
    if rc < 0:
        return "FAIL", f"died by signal {-rc}"
    error_out = any(l.startswith("ERROR") for l in out.splitlines())
    error_log = any(l.startswith("ERROR") for l in log.splitlines())
    if rc != 0:
        if error_out and error_log:
            return "rejected", ""
        missing = [name for name, has in (("stdout", error_out), ("log.lammps", error_log))
                   if not has]
        return "FAIL", f"exit status {rc} without an ERROR line in {' and '.join(missing)}"
    if error_out or error_log:
        return "FAIL", "exit status 0 after an ERROR line"
    values = thermo_values(log)
    if values is None:
        return "FAIL", "exit status 0, but the run did not complete"
    bad = [v for v in values if not _finite(v)]
    if bad:
        return "FAIL", f"accepted, but thermo output holds {bad[0]}"
    return "accepted", ""


def _finite(word):
    try:
        return math.isfinite(float(word))
    except ValueError:
        return False


def run_one(args, mutant, index):
    style, kokkos, desc, original, mutated, text = mutant
    work = tempfile.mkdtemp(prefix=f"fuzz{index:04d}_", dir=args.work)
    with open(os.path.join(work, "in.fuzz"), "w") as f:
        f.write(text)
    cmd = ["timeout", "-k", "5", str(args.timeout), args.lmp, "-in", "in.fuzz", "-log", "log.lammps"]
    if kokkos:
        cmd += KOKKOS
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
               LD_LIBRARY_PATH=args.plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
    start = time.time()
    with open(os.path.join(work, "out.txt"), "w") as out, \
            open(os.path.join(work, "err.txt"), "w") as err:
        rc = subprocess.call(cmd, cwd=work, stdout=out, stderr=err, stdin=subprocess.DEVNULL,
                             env=env)
    seconds = time.time() - start

    def read(name):
        try:
            with open(os.path.join(work, name), errors="replace") as f:
                return f.read()
        except OSError:
            return ""
    out, err, log = read("out.txt"), read("err.txt"), read("log.lammps")
    outcome, why = classify(rc, out, log)
    shutil.rmtree(work, ignore_errors=True)
    return dict(style=style, desc=desc, original=original, mutated=mutated, rc=rc,
                outcome=outcome, why=why, seconds=seconds,
                tails={n: "\n".join(t.splitlines()[-6:]) for n, t in
                       (("stdout", out), ("stderr", err), ("log.lammps", log))})


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--lmp", required=True)
    p.add_argument("--plugin-dir", required=True)
    p.add_argument("--jobs", type=int, default=int(os.environ.get("PW_FUZZ_JOBS", "2")))
    p.add_argument("--timeout", type=int, default=20)
    p.add_argument("--accel", choices=("cpu", "kk", "both"), default="both")
    p.add_argument("--count", default=os.environ.get("PW_FUZZ_COUNT", "120"))
    p.add_argument("--seed", type=int, default=int(os.environ.get("PW_FUZZ_SEED", "1")))
    p.add_argument("--failures", default="fuzz_failures.txt")
    p.add_argument("--outcomes", default=None, help="write every outcome here (tab-separated)")
    p.add_argument("--work", default=None)
    p.add_argument("--list", action="store_true", help="print the mutants and stop")
    args = p.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    args.plugin_dir = os.path.abspath(args.plugin_dir)

    if args.accel != "cpu" and os.environ.get("PW_HOST_KOKKOS") == "0":
        if args.accel == "both":
            print("this LAMMPS has no KOKKOS package (PW_HOST_KOKKOS=0): use --accel cpu")
            return 2
        print("skipped: this LAMMPS has no KOKKOS package, so the plugin has no /kk styles")
        return 77
    mutants = all_mutants(args.accel)
    chosen = list(range(len(mutants)))
    if args.count != "all" and int(args.count) < len(mutants):
        chosen = sample(mutants, int(args.count), args.seed)
    if args.list:
        for i in chosen:
            m = mutants[i]
            print(f"{i:5d} {m[0]:24s} {m[2]:40s} {m[4]}")
        return 0
    # the valid inputs first: each must run cleanly, or the fuzzing means nothing
    todo = list(valid_inputs(args.accel)) + [mutants[i] for i in chosen]
    own_work = args.work is None
    if own_work:
        args.work = tempfile.mkdtemp(prefix="pw_fuzz_")
    what = {"cpu": "CPU", "kk": "/kk", "both": "CPU and /kk"}[args.accel]
    print(f"{len(mutants)} mutants of {len(STYLES)} inputs ({what}); running "
          f"{len(chosen)} (seed {args.seed}) and the {len(todo) - len(chosen)} valid inputs "
          f"on {args.jobs} jobs, {args.timeout} s each at most", flush=True)
    start = time.time()
    nvalid = len(todo) - len(chosen)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        run = lambda im: run_one(args, im[1], im[0])
        valid = list(pool.map(run, enumerate(todo[:nvalid])))
        for r in valid:
            if r["outcome"] != "accepted":
                r["outcome"], r["why"] = "FAIL", r["why"] or "rejected"
        # a valid input that does not run cleanly makes the mutants meaningless
        clean = all(r["outcome"] == "accepted" for r in valid)
        fuzzed = list(pool.map(run, enumerate(todo[nvalid:], nvalid))) if clean else []
    if own_work:
        shutil.rmtree(args.work, ignore_errors=True)
    counts = {}
    for r in fuzzed:
        counts.setdefault(r["style"], {}).setdefault(r["outcome"], 0)
        counts[r["style"]][r["outcome"]] += 1
    print(f"{'style':24s} {'rejected':>9s} {'accepted':>9s} {'FAIL':>6s}")
    for style in sorted(counts):
        c = counts[style]
        print(f"{style:24s} {c.get('rejected', 0):9d} {c.get('accepted', 0):9d} "
              f"{c.get('FAIL', 0):6d}")
    total = {o: sum(1 for r in fuzzed if r["outcome"] == o) for o in ("rejected", "accepted", "FAIL")}
    print(f"{len(fuzzed)} mutants: {total['rejected']} rejected with a message, "
          f"{total['accepted']} accepted and ran cleanly, {total['FAIL']} failed; "
          f"valid inputs: {sum(r['outcome'] == 'accepted' for r in valid)}/{len(valid)} clean; "
          f"{time.time() - start:.0f} s", flush=True)

    if args.outcomes:
        with open(args.outcomes, "w") as f:
            for r in valid + fuzzed:
                first_error = next((l for l in r["tails"]["stdout"].splitlines()
                                    if l.startswith("ERROR")), "")
                f.write("\t".join([r["style"], r["outcome"], str(r["rc"]), r["desc"], r["mutated"],
                                   r["why"], first_error]) + "\n")
    failures = [r for r in valid + fuzzed if r["outcome"] == "FAIL"]
    with open(args.failures, "w") as f:
        for r in failures:
            f.write(f"## {r['style']}: {r['desc']}: {r['why']}\n")
            f.write(f"    original: {r['original']}\n    mutant:   {r['mutated']}\n")
            f.write(f"    exit status {r['rc']}, {r['seconds']:.1f} s\n")
            for name, tail in r["tails"].items():
                f.write(f"    --- {name}\n" + "".join(f"    | {l}\n" for l in tail.splitlines()))
            f.write("\n")
    for r in failures[:20]:
        print(f"FAIL {r['style']}: {r['desc']}: {r['why']}\n     {r['mutated']}")
    if len(failures) > 20:
        print(f"... and {len(failures) - 20} more")
    if failures:
        print(f"details in {os.path.abspath(args.failures)}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
