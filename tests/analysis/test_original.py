"""porewater_analysis.original on a synthetic time series whose answers are known by
construction (no LAMMPS): PYTHONPATH=analysis python3 -m unittest discover -s tests/analysis"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

from porewater_analysis import original
from porewater_analysis.report import parameters
from porewater_analysis.timeseries import load, run_parameters

ANALYSIS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "analysis")
# a period of 2 s in 1024 rows: every time, phase and cycle boundary exact in binary, no row
# on a phase the conditions compare with (0.2, 0.6: 204.8, 614.4 rows)
PERIOD, ROWS, CYCLES = 2.0, 1024, 3
SIGMA0, AMP, TAU, HEIGHT = 45.0e3, 40.0e3, 10.0e3, 0.25
N_EXP, A_RATE = 7.0, 1.0e4          # creep: gamma_dot = A (tau/N)^n, 1/s
RATE_SCALE = 2.415e-7 / original.WATER_VISCOSITY
SLIP, STUCK_TINY, NOT_STUCK = 2.0, 5e-9, 2e-8     # m/s
Z_MIN_ROW, Z_ODD_ROW, Z_ORIGINAL_MIN_ROW = 400, 401, 800   # rows within a cycle


def synthetic():
    """rows k = 1 .. CYCLES*ROWS at t = k PERIOD/ROWS: creep at A (tau/N)^n below tau/N 0.38
    (a slow 1e-4 m/s above it), negative velocities at phases 0.30-0.31 and 0.95-1, a slip of
    SLIP m/s over phases 0.7-0.8, stuck (v = 0) over 0.85-0.95 but for one row of 5e-9 m/s
    (stuck) and one of 2e-8 m/s (not); coordination minima at known rows"""
    k = np.arange(1, CYCLES * ROWS + 1)
    t = k * (PERIOD / ROWS)
    row = k % ROWS
    phase = row / ROWS
    n_applied = SIGMA0 + AMP * np.sin(2 * np.pi * t / PERIOD)
    friction = TAU / n_applied
    vx = np.where(friction < 0.38, HEIGHT * A_RATE * friction ** N_EXP, 1e-4)
    vx[phase >= 0.6] = 1e-3
    vx[(phase >= 0.30) & (phase < 0.31)] = -1e-4
    vx[(phase >= 0.7) & (phase < 0.8)] = SLIP
    vx[(phase >= 0.85) & (phase < 0.95)] = 0.0
    vx[row == 922] = STUCK_TINY
    vx[row == 924] = NOT_STUCK
    vx[phase >= 0.95] = -1e-5
    cycle = k // ROWS + 1
    ours = np.full(len(k), 4.5)
    ours[row == Z_MIN_ROW] = 3.0 + 0.1 * cycle[row == Z_MIN_ROW]
    ours[row == Z_ODD_ROW] = 2.0       # an odd row: not among the original's samples
    theirs = np.full(len(k), 4.0)
    theirs[row == Z_ORIGINAL_MIN_ROW] = 0.05 * cycle[row == Z_ORIGINAL_MIN_ROW]
    return {"time": t, "vx_top": vx, "x_top": np.cumsum(vx) * (PERIOD / ROWS),
            "tau_resist": np.zeros_like(t), "z_wall": np.full_like(t, HEIGHT),
            "N_grains": n_applied, "N_applied": n_applied, "p_top": -AMP * np.sin(2 * np.pi * t / PERIOD),
            "p_mean": np.zeros_like(t), "coordination": ours, "coordination_original": theirs}, k


class Original(unittest.TestCase):
    def setUp(self):
        self.series, self.k = synthetic()
        self.even = self.k % 2 == 0
        self.phase = (self.k % ROWS) / ROWS
        self.cycle = self.k // ROWS + 1

    def test_shear_velocity_of_a_negative_vx_is_zero(self):
        np.testing.assert_array_equal(original.shear_velocity(np.array([-1e-3, 0.0, 2e-3])),
                                      [0.0, 0.0, 2e-3])
        self.assertEqual(original.shear_strain_rate(np.array([0.5]), np.array([0.25]))[0], 2.0)

    def test_original_samples_every_second_row(self):
        s = original.original_samples(self.series, PERIOD)
        np.testing.assert_array_equal(s["time"], self.series["time"][1::2])
        self.assertEqual(set(s), set(self.series))

    def test_creep_fit_recovers_n(self):
        fit = original.creep_fit(self.series, PERIOD, TAU, RATE_SCALE)
        self.assertAlmostEqual(fit["n"], N_EXP, delta=1e-6)
        self.assertAlmostEqual(fit["A"] / (A_RATE * RATE_SCALE), 1.0, delta=1e-6)
        self.assertLess(fit["n_sigma"], 1e-6)

    def test_creep_fit_drops_exactly_the_samples_it_should(self):
        vx, n_applied = self.series["vx_top"], self.series["N_applied"]
        rate = np.maximum(vx, 0.0) / HEIGHT
        window = (self.phase > 0.2) & (self.phase < 0.6)
        reasons = {"not a sample": ~self.even, "cycle 1": self.cycle < 2,
                   "phase outside (0.2, 0.6)": ~window, "v <= 0": vx <= 0,
                   "tau/N >= 0.38": TAU / n_applied >= 0.38,
                   "rate above 0.1 (5 s/period) 1/s": rate * PERIOD >= 0.5}
        keep = ~np.any(list(reasons.values()), axis=0)
        fit = original.creep_fit(self.series, PERIOD, TAU, RATE_SCALE)
        np.testing.assert_array_equal(fit["time"], self.series["time"][keep])
        self.assertEqual(fit["count"], keep.sum())
        np.testing.assert_allclose(fit["rate"], rate[keep] * RATE_SCALE, rtol=1e-12)
        # each condition alone drops some candidate the others would keep
        for name, dropped in reasons.items():
            others = ~np.any([d for n, d in reasons.items() if n != name], axis=0)
            self.assertTrue(np.any(dropped & others), name)

    def test_creep_fit_per_cycle(self):
        per_cycle = original.creep_fit_per_cycle(self.series, PERIOD, TAU, RATE_SCALE)
        self.assertEqual([f["cycle"] for f in per_cycle], list(range(1, CYCLES + 1)))
        pooled = original.creep_fit(self.series, PERIOD, TAU, RATE_SCALE)
        self.assertEqual(sum(f["count"] for f in per_cycle[1:]), pooled["count"])
        for f in per_cycle:
            self.assertAlmostEqual(f["n"], N_EXP, delta=1e-6)

    def test_least_squares_minimum_recovers_n_in_any_units(self):
        """the minimum the original's fit seeks: n of the noise-free law, whether the rates are
        of order 1 or 1e-9 (the reduced case's scaled rates), A scaled with them"""
        fit = original.creep_fit(self.series, PERIOD, TAU, RATE_SCALE)
        for units in (1.0, 1e-9):
            best = original.creep_fit_minimum(fit["friction"], fit["rate"] * units)
            self.assertAlmostEqual(best["n"], N_EXP, delta=1e-6)
            self.assertAlmostEqual(best["A"] / (A_RATE * RATE_SCALE * units), 1.0, delta=1e-5)
            self.assertLess(best["interval"][1] - best["interval"][0], 0.02)

    def test_least_squares_profile_is_the_sum_of_squares_at_the_best_a(self):
        """at each n: the A of a one-column linear least-squares fit and its residual sum"""
        rng = np.random.default_rng(3)
        f = rng.uniform(0.1, 0.38, 200)
        r = 1e-9 * f ** 6 * rng.lognormal(0.0, 0.5, 200)
        a, ssr = original.least_squares_profile(f, r, [2.0, 6.5, 11.0])
        for k, n in enumerate([2.0, 6.5, 11.0]):
            (a_ls,), (ssr_ls,), _, _ = np.linalg.lstsq((f ** n)[:, None], r, rcond=None)
            self.assertAlmostEqual(a[k] / a_ls, 1.0, delta=1e-12)
            self.assertAlmostEqual(ssr[k] / ssr_ls, 1.0, delta=1e-9)
        best = original.creep_fit_minimum(f, r)
        self.assertLess(best["interval"][0], best["n"])
        self.assertGreater(best["interval"][1], best["n"])
        self.assertLessEqual(best["ssr"], original.least_squares_profile(f, r, [best["n"] + 0.01])[1][0])
        self.assertLessEqual(best["ssr"], original.least_squares_profile(f, r, [best["n"] - 0.01])[1][0])

    def test_stick_fraction_intervals_and_band_exit(self):
        v = np.maximum(self.series["vx_top"], 0.0)
        rows = original.stick(self.series, PERIOD, TAU)
        self.assertEqual(len(rows), CYCLES)
        for r in rows:
            sample = self.even & (self.cycle == r["cycle"])
            stuck = sample & (v <= 1e-8)
            self.assertEqual(r["stick_fraction"], stuck.sum() / sample.sum())
            self.assertFalse(np.any(stuck & (self.series["vx_top"] == NOT_STUCK)))
            # runs of stuck samples: the negative 0.30-0.31, then 0.85 to the end but the
            # 2e-8 row (924) that splits it
            starts = [p for p, _ in r["stick_intervals"]]
            np.testing.assert_array_equal(starts, [308 / ROWS, 872 / ROWS, 926 / ROWS])
            self.assertEqual(r["stick_intervals"][1][1], 922 / ROWS)
            slip = self.phase[sample & (self.series["vx_top"] == SLIP)]
            after = self.phase[sample & (self.phase >= 0.8)]
            self.assertEqual(r["exit_onset"], slip.min())
            self.assertEqual(r["exit_end"], after.min())

    def test_coordination_picks_min_and_phase(self):
        rows = original.coordination(self.series, PERIOD)
        for r in rows:
            self.assertEqual(r["ours"]["min"], 3.0 + 0.1 * r["cycle"])
            self.assertEqual(r["ours"]["min_phase"], Z_MIN_ROW / ROWS)
            self.assertEqual(r["original"]["min"], 0.05 * r["cycle"])
            self.assertEqual(r["original"]["min_phase"], Z_ORIGINAL_MIN_ROW / ROWS)
            self.assertEqual(r["original"]["creep"], 4.0)
        old_run = {k: v for k, v in self.series.items() if k != "coordination_original"}
        self.assertIsNone(original.coordination(old_run, PERIOD)[0]["original"])


PARAMS = {"freq": 1.0 / PERIOD, "tau": TAU, "amp": AMP, "mu_f": 2.415e-7, "dt": 1.23e-5,
          "integrator": "nve/sphere"}


def write_run(folder, series, params):
    names = list(series)
    data = np.column_stack([series[n] for n in names])
    half = len(data) // 2
    with open(os.path.join(folder, "timeseries.txt"), "w") as f:
        f.write("# " + " ".join(names) + "\n")
        np.savetxt(f, data[:half], fmt="%.17g")
        f.write("# continued from checkpoint.restart\n")
        np.savetxt(f, data[half:], fmt="%.17g")
    with open(os.path.join(folder, "checkpoint_params.txt"), "w") as f:
        f.write("# the parameters of the run that wrote checkpoint.restart (in.checkpoint_params)\n")
        for key, value in params.items():
            f.write("variable ck_%s index %s\n" % (key, value))


class RunFolder(unittest.TestCase):
    def test_load_and_parameters(self):
        series, _ = synthetic()
        with tempfile.TemporaryDirectory() as d:
            write_run(d, series, PARAMS)
            back = load(os.path.join(d, "timeseries.txt"))
            np.testing.assert_array_equal(back["time"], series["time"])
            self.assertEqual(run_parameters(d), PARAMS)
            write_run(d, series, {k: v for k, v in PARAMS.items() if k != "mu_f"})
            got, notes = parameters(d)
            self.assertEqual(got["period"], PERIOD)
            self.assertEqual(got["rate_scale"], 2.415e-7 / original.WATER_VISCOSITY)
            self.assertEqual(len(notes), 1)
            self.assertIn("mu_f", notes[0])

    def test_load_reads_a_series_kept_compressed(self):
        """timeseries.txt.xz where timeseries.txt is missing: the same columns, comments
        skipped"""
        import lzma
        series, _ = synthetic()
        with tempfile.TemporaryDirectory() as d:
            write_run(d, series, PARAMS)
            path = os.path.join(d, "timeseries.txt")
            with open(path, "rb") as f, lzma.open(path + ".xz", "wb") as out:
                out.write(f.read())
            os.remove(path)
            back = load(path)
            for name in series:
                np.testing.assert_array_equal(back[name], series[name])

    def test_load_of_a_series_without_rows(self):
        """a run stopped before its first row: every column, empty"""
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "timeseries.txt")
            with open(path, "w") as f:
                f.write("# time vx_top x_top\n")
            back = load(path)
            self.assertEqual(sorted(back), ["time", "vx_top", "x_top"])
            self.assertTrue(all(len(v) == 0 for v in back.values()))

    def test_cli_writes_the_table_and_the_figure(self):
        series, _ = synthetic()
        with tempfile.TemporaryDirectory() as d:
            write_run(d, series, PARAMS)
            env = dict(os.environ, PYTHONPATH=os.pathsep.join(
                [ANALYSIS] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
            out = subprocess.run([sys.executable, "-m", "porewater_analysis", d], env=env,
                                 capture_output=True, text=True)
            self.assertEqual(out.returncode, 0, out.stderr)
            with open(os.path.join(d, "analysis.md")) as f:
                table = f.read()
            self.assertTrue(os.path.getsize(os.path.join(d, "analysis.png")) > 0)
            for k in range(1, CYCLES + 1):
                self.assertIn("\n| %d | " % k, table)
            self.assertIn("| 2-%d pooled | " % CYCLES, table)
            self.assertIn("7.00 ± 0.00", table)
            self.assertIn("Period 2 s", table)
            # the landings (1 and 2: landing 3's window runs past the rows) and the fit again
            # without its fastest samples, per cycle and pooled, on both grids
            self.assertIn("## The landings", table)
            for k in (1, 2):
                self.assertIn("\n| %d | " % k, table.split("## The landings")[1])
            self.assertNotIn("\n| 3 | ", table.split("## The landings")[1])
            left_out = table.split("## The original's fit, its fastest samples left out")[1]
            for fit in ["cycle %d" % k for k in range(1, CYCLES + 1)] + ["2-%d pooled" % CYCLES]:
                for offset in (0, 1):
                    self.assertIn("| %s | %d | " % (fit, offset), left_out)
            # every sample of both grids with its cut; those kept on grid 0 are the pooled fit's
            with open(os.path.join(d, "analysis_fit_samples.txt")) as f:
                rows = [line.split(None, 5) for line in f if not line.startswith("#")]
            self.assertEqual(len(rows), len(series["time"]))
            kept = [float(r[1]) for r in rows if r[0] == "0" and r[5].strip() == "kept"]
            pooled = original.creep_fit(series, PERIOD, TAU, RATE_SCALE)
            np.testing.assert_allclose(kept, pooled["time"], atol=1e-5)


if __name__ == "__main__":
    unittest.main()
