"""python3 -m porewater_analysis RUN_DIR [--out PREFIX] [--cycles N]: both estimators on a run
folder of examples/tidal_shear (timeseries.txt, checkpoint_params.txt): PREFIX.md, the table
cycle by cycle, and PREFIX.png, the figure (analysis/README.md)."""
import argparse
import os

from .report import analyse_run, markdown, plot
from .timeseries import load


def main():
    ap = argparse.ArgumentParser(prog="python3 -m porewater_analysis", description=__doc__)
    ap.add_argument("run_dir", metavar="RUN_DIR",
                    help="a run folder: timeseries.txt and checkpoint_params.txt")
    ap.add_argument("--out", metavar="PREFIX",
                    help="writes PREFIX.md and PREFIX.png (default RUN_DIR/analysis)")
    ap.add_argument("--cycles", type=int, metavar="N",
                    help="the first N forcing cycles only (default: every whole cycle)")
    args = ap.parse_args()
    prefix = args.out or os.path.join(args.run_dir, "analysis")
    result = analyse_run(args.run_dir, args.cycles)
    lines = markdown(result, args.run_dir) + ["", "![the cycles](%s.png)" % os.path.basename(prefix)]
    with open(prefix + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    plot(load(os.path.join(args.run_dir, "timeseries.txt")), result, prefix + ".png")
    print("\n".join(lines))
    print("wrote %s.md, %s.png" % (prefix, prefix))


if __name__ == "__main__":
    main()
