"""python3 -m porewater_analysis RUN_DIR [--out PREFIX] [--cycles N] [--data-file PATH]: both
estimators on a run folder of examples/tidal_shear (timeseries.txt, checkpoint_params.txt):
PREFIX.md, the table cycle by cycle, the landings and the original's fit with its fastest
samples left out; PREFIX.png, the figure; PREFIX_fit_samples.txt, the original's samples with
the cut that drops each (analysis/README.md)."""
import argparse
import os

from .report import DATA_FILE, analyse_run, fit_samples_lines, markdown, plot
from .timeseries import load


def main():
    ap = argparse.ArgumentParser(prog="python3 -m porewater_analysis", description=__doc__)
    ap.add_argument("run_dir", metavar="RUN_DIR",
                    help="a run folder: timeseries.txt and checkpoint_params.txt")
    ap.add_argument("--out", metavar="PREFIX",
                    help="writes PREFIX.md and PREFIX.png (default RUN_DIR/analysis)")
    ap.add_argument("--cycles", type=int, metavar="N",
                    help="the first N forcing cycles only (default: every whole cycle)")
    ap.add_argument("--data-file", metavar="PATH",
                    help="the original run's data file read beside each landing (default: "
                         "the repository's bench/common/original_run_contacts.txt; 'none': "
                         "without it)")
    args = ap.parse_args()
    prefix = args.out or os.path.join(args.run_dir, "analysis")
    data_file = {None: DATA_FILE, "none": None}.get(args.data_file, args.data_file)
    if args.data_file not in (None, "none") and not os.path.exists(data_file):
        ap.error("no data file %s" % data_file)    # the default, where missing: without it
    result = analyse_run(args.run_dir, args.cycles, data_file)
    lines = markdown(result, args.run_dir, os.path.basename(prefix) + "_fit_samples.txt") + [
        "", "![the cycles](%s.png)" % os.path.basename(prefix)]
    with open(prefix + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(prefix + "_fit_samples.txt", "w") as f:
        f.write("\n".join(fit_samples_lines(result)) + "\n")
    plot(load(os.path.join(args.run_dir, "timeseries.txt")), result, prefix + ".png")
    print("\n".join(lines))
    print("wrote %s.md, %s.png, %s_fit_samples.txt" % (prefix, prefix, prefix))


if __name__ == "__main__":
    main()
