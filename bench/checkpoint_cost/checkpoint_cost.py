#!/usr/bin/env python3
"""What checkpointing costs examples/tidal_shear: the default chunks (0.05 cycle, a
checkpoint written and renamed after each) against one chunk for the same steps, run side
by side (one core each). The cost is measured inside each run rather than as a difference
of wall times, which the noise of a shared machine would swamp: LAMMPS' "Total wall time"
less the loop times of its runs is what the run spends outside its time steps (setup of
each chunk: neighbour lists, the fixes' setup; the checkpoint writes; reading the input):
the process's wall time (polled every 20 ms) less the loop times in its log.

    bench/checkpoint_cost/checkpoint_cost.py [--cycles 0.25] [--work DIR]   -> checkpoint_cost_results.md
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import out_dir  # noqa: E402
from common.runs import loop_time, prepare  # noqa: E402

ENV = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--cycles", type=float, default=0.25)
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="pw_checkpoint_cost_")
    cases = {"chunks of 0.05 cycle (default)": {}, "one chunk": {"checkpoint": 1e9}}
    load = open("/proc/loadavg").read().split()[0]
    pairs = []
    for order in (list(cases), list(cases)[::-1]):    # started in both orders
        procs, dirs, ended, began = {}, {}, {}, {}
        for name in order:
            d = os.path.join(work, f"pair{len(pairs) + 1}_" + re.sub(r"\W+", "_", name))
            prepare(d)
            cmd = ["lmp", "-in", "in.tidal_shear", "-var", "cycles", str(args.cycles), "-log",
                   "log.lammps", "-screen", "none"]
            for k, v in cases[name].items():
                cmd += ["-var", k, str(v)]
            began[name] = time.time()
            procs[name], dirs[name] = subprocess.Popen(cmd, cwd=d, env=ENV), d
        while len(ended) < len(procs):
            for name, p in procs.items():
                if name not in ended and p.poll() is not None:
                    if p.returncode != 0:
                        sys.exit(f"{name}: lmp failed in {dirs[name]}")
                    ended[name] = time.time() - began[name]
            time.sleep(0.02)
        rows = []
        for name in cases:
            log = os.path.join(dirs[name], "log.lammps")
            loop, steps = loop_time(log, last=False)
            runs = len(re.findall(r"Loop time of", open(log).read()))
            rows.append((name, runs, steps, loop, ended[name], ended[name] - loop))
        pairs.append((order[0], rows))
    commit = subprocess.run(["git", "describe", "--always", "--dirty=+uncommitted changes"],
                            cwd=HERE, capture_output=True, text=True).stdout.strip()
    lines = [f"# Cost of checkpointing examples/tidal_shear\n",
             f"Measured by `bench/checkpoint_cost/checkpoint_cost.py --cycles {args.cycles}` on commit {commit}, "
             f"the 2-core development machine, the two runs side by side, twice, started in "
             f"either order (load average {load} at the start).\n",
             "| pair | started first | run | runs (chunks) | steps | loop time (s) | process wall (s) | outside the steps (s) |",
             "|---|---|---|---|---|---|---|---|"]
    costs, ratios = [], []
    for k, (first, rows) in enumerate(pairs):
        for name, runs, steps, loop, wall, outside in rows:
            lines.append(f"| {k + 1} | {first} | {name} | {runs} | {steps} | {loop:.2f} | "
                         f"{wall:.2f} | {outside:.2f} |")
        chunked, base = rows
        costs.append((chunked[5] - base[5], chunked[1] - base[1], chunked[3]))
        ratios.append(chunked[3] / base[3] - 1)
    lines.append("")
    for extra, chunks, loop in costs:
        lines.append(f"Checkpointing costs {extra:.2f} s over {chunks} more chunks "
                     f"({extra / max(chunks, 1):.3f} s each, ±0.02 s of polling): "
                     f"{100 * extra / loop:.2f} % of the loop time (the limit: 1 %).")
    lines.append("")
    lines.append("The loop times differ by " + ", ".join(f"{100 * r:+.1f} %" for r in ratios) +
                 " (chunked against one chunk, pairs 1 and 2). A chunk's setup and its "
                 "checkpoint lie outside its loop and the steps do the same work, so this is the "
                 "noise of two runs on shared cores (it takes either sign over repeated runs of "
                 "this script); what chunking costs is the column outside the steps.")
    out = os.path.join(out_dir(HERE), "checkpoint_cost_results.md")
    open(out, "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
