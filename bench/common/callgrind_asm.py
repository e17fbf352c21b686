#!/usr/bin/python3
"""Per-instruction execution counts of one function, from a callgrind profile.

valgrind 3.19 cannot read the line tables GCC 12 writes for inlined code (the kernels'
costs all land on "unidentified lines"), so this maps callgrind's instruction addresses
onto `objdump -d` of the object instead and prints the function as runs of instructions
executed equally often: a loop body is one run, its count is the trip count.

Usage:
    valgrind --tool=callgrind --dump-instr=yes --callgrind-out-file=OUT lmp -in ...
    bench/common/callgrind_asm.py OUT path/to/porewater_styles.so SYMBOL_SUBSTRING [--min COUNT]
(the styles' object: plugin/porewater_styles.so since the plugin has a loader, porewater.so;
plugin/porewater.so itself in builds before that)
SYMBOL_SUBSTRING picks, of the symbols (demangled) containing it, the one whose instructions
ran most; pass enough of it to be unique, e.g. 'FixDarcyPressure::deposit_grains(double)'. --min hides runs executed fewer
times (default 1000).
"""
import argparse, collections, re, subprocess, sys


def self_costs(path, obj):
    """{address: self cost} of the instructions of object `obj` (callgrind's first event)."""
    names, cost = {}, collections.Counter()
    current, addr, after_calls = "", 0, False

    def name(kind, value):    # "(id) name" defines a compressed name, "(id)" uses it
        m = re.match(r"\((\d+)\)(?: (.*))?", value)
        if not m:
            return value
        if m.group(2):
            names[(kind, m.group(1))] = m.group(2)
        return names.get((kind, m.group(1)), "")

    for line in open(path):
        if line.startswith("ob="):
            current = name("ob", line[3:].strip())
        elif line.startswith("cob="):
            name("ob", line[4:].strip())
        elif line.startswith("calls="):
            after_calls = True    # the next cost line is a call's inclusive cost
        elif line[:1].isdigit() or line[:1] in "+-*":
            fields = line.split()
            tok = fields[0]
            addr = (addr if tok == "*" else addr + int(tok[1:], 0) if tok[0] == "+"
                    else addr - int(tok[1:], 0) if tok[0] == "-" else int(tok, 0))
            if after_calls:
                after_calls = False
            elif obj in current and len(fields) > 2:
                cost[addr] += int(fields[2])
    return cost


def symbol_range(obj, pattern, cost):
    """the symbol containing `pattern` whose instructions ran most (a function and its
    clones, e.g. `.isra.0`, share a name)"""
    syms = []
    for line in subprocess.run(["nm", "-C", "-n", obj], capture_output=True, text=True).stdout.splitlines():
        parts = line.split(" ", 2)
        if len(parts) == 3 and parts[0]:
            syms.append((int(parts[0], 16), parts[2]))
    found = []
    for k, (start, sym) in enumerate(syms):
        if pattern in sym:
            stop = next((a for a, _ in syms[k + 1:] if a > start), start + 0x10000)
            found.append((sum(c for a, c in cost.items() if start <= a < stop), start, stop, sym))
    if not found:
        sys.exit(f"no symbol containing {pattern!r} in {obj}")
    return max(found)[1:]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("profile")
    ap.add_argument("object")
    ap.add_argument("symbol")
    ap.add_argument("--min", type=int, default=1000)
    args = ap.parse_args()
    cost = self_costs(args.profile, args.object.rsplit("/", 1)[-1])
    start, stop, sym = symbol_range(args.object, args.symbol, cost)
    dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-C", f"--start-address={start}",
                          f"--stop-address={stop}", args.object], capture_output=True, text=True).stdout
    rows = []
    for line in dis.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(.*)", line)
        if m:
            rows.append((int(m.group(1), 16), cost.get(int(m.group(1), 16), 0),
                         m.group(2).split("<")[0].strip()))
    print(f"{sym}\n{sum(c for _, c, _ in rows):,} instructions executed")
    run = []
    for row in rows + [(0, -1, "")]:    # the sentinel closes the last run
        if run and row[1] != run[0][1]:
            count = run[0][1]
            if count >= args.min:
                print(f"{count:>10,} x {len(run):3d} = {count * len(run):>13,}  @{run[0][0]:x}: "
                      + " | ".join(r[2] for r in run))
            run = []
        run.append(row)


if __name__ == "__main__":
    main()
