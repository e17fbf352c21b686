"""porewater_analysis.original: the original's creep fit at the edges of its filters, each
expected behaviour from the line of python/halfshear-darcy-rate-dependence.py (sphere at
116df3b) that sets it; the samples it lists with their cuts (fit_samples); the grids of
every second row (offsets); the fit again without its fastest samples (leave_fastest_out)."""
import unittest

import numpy as np

from porewater_analysis import original

# the original's own cycle (Table S1: 5 s, an output file every 0.01 s: one row per file,
# stride 1), tau/N reaching 0.38 at N = 25 kPa
PERIOD, SPACING, CYCLES = 5.0, 0.01, 3
SIGMA0, AMP, TAU, HEIGHT = 80.0e3, 70.0e3, 9.5e3, 0.25
N_EXP, A_RATE = 5.0, 2.0                # creep: gamma_dot = A (tau/N)^n, 1/s, well under 0.1
THRESHOLD = 0.1                         # 1/s: the rate's cut over a 5 s cycle, rate_scale 1


def series(times=None):
    """rows k = 1 .. CYCLES * 500 at t = k SPACING (or `times`), creeping at A (tau/N)^n"""
    k = np.arange(1, CYCLES * 500 + 1)
    t = k * SPACING if times is None else times
    n_applied = SIGMA0 + AMP * np.sin(2 * np.pi * t / PERIOD)
    vx = HEIGHT * A_RATE * (TAU / n_applied) ** N_EXP
    return {"time": t, "vx_top": vx, "z_wall": np.full_like(t, HEIGHT), "N_applied": n_applied}


def cut_at(s, time, first_cycle=2):
    """the cut fit_samples gives the sample at `time`"""
    rows = [r for r in original.fit_samples(s, PERIOD, TAU, 1.0, first_cycle) if r["time"] == time]
    assert len(rows) == 1, time
    return rows[0]["cut"]


class FilterEdges(unittest.TestCase):
    def test_the_rows_stand_where_the_edges_are(self):
        s = series()
        for edge in (6.0, 8.0, 11.0, 13.0):
            self.assertIn(edge, s["time"])
        self.assertEqual(TAU / 25.0e3, 0.38)
        self.assertEqual(original.shear_strain_rate(np.array([THRESHOLD * HEIGHT]),
                                                    np.array([HEIGHT]))[0], THRESHOLD)

    def test_a_window_end_is_out_and_its_first_sample_in(self):
        # lines 101-111: (t > 6.0) & (t < 8.0), (t > 11.0) & (t < 13.0): open. t is the
        # sample's time, currentTime() of its file (line 79), which src/device.cu writes once
        # its file clock reaches 0.01 s (lines 2543-2544, 2576, 2679): file 600 at 600 m dt
        # >= 6 s. A sample exactly at an end (6, 8, 11, 13 s) is out; one a hair inside it is
        # in: after 6 s stands the window's first sample, as the original's file 600 does
        s = series()
        for edge in (6.0, 8.0, 11.0, 13.0):
            self.assertEqual(cut_at(s, edge), "outside 1-3 s", edge)
        times = s["time"].copy()
        first, last = (np.nextafter(6.0, 7.0), np.nextafter(11.0, 12.0)), \
            (np.nextafter(8.0, 7.0), np.nextafter(13.0, 12.0))
        for edge, hair in zip((6.0, 11.0, 8.0, 13.0), first + last):
            times[np.nonzero(times == edge)[0]] = hair
        moved = series(times)
        for hair in first + last:
            self.assertEqual(cut_at(moved, hair), "kept", hair)
        # the original's files stand at or after j 0.01 s: with every time a hair after it,
        # each window keeps 200 samples, files 600-799 and 1100-1299; with every time
        # exactly on it, 199 (600 and 1100 out)
        after = series(np.arange(1, CYCLES * 500 + 1) * SPACING * (1 + 1e-12))
        self.assertEqual(original.creep_fit(after, PERIOD, TAU)["count"], 400)
        self.assertEqual(original.creep_fit(s, PERIOD, TAU)["count"], 398)

    def test_tau_over_n_at_038_is_out(self):
        # line 99: tau_nonzero/N_nonzero < 0.38, strict: a sample exactly at 0.38 is out, one
        # just below it in (the window's tau/N stay below 0.26 at Table S1's N: the rows here
        # are given the N that puts them on the edge)
        s = series()
        at, below = np.nonzero(s["time"] == 7.0)[0][0], np.nonzero(s["time"] == 7.5)[0][0]
        s["N_applied"][at] = 25.0e3
        s["N_applied"][below] = np.nextafter(25.0e3, 3e4)
        self.assertLess(TAU / s["N_applied"][below], 0.38)
        s["vx_top"][[at, below]] = HEIGHT * 1e-3
        self.assertEqual(cut_at(s, 7.0), "tau/N >= 0.38")
        self.assertEqual(cut_at(s, 7.5), "kept")

    def test_rate_at_the_threshold_is_out(self):
        # line 100: shearstrainrate_nonzero < 0.1*t_DEM_to_t_real, strict, the rate being
        # shearStrainRate() * t_DEM_to_t_real (line 77): the unscaled rate at 0.1 1/s is out
        s = series()
        at, below = np.nonzero(s["time"] == 7.0)[0][0], np.nonzero(s["time"] == 7.5)[0][0]
        s["vx_top"][at] = THRESHOLD * HEIGHT
        s["vx_top"][below] = np.nextafter(THRESHOLD * HEIGHT, 0.0)
        self.assertEqual(cut_at(s, 7.0), "rate >= 0.1")
        self.assertEqual(cut_at(s, 7.5), "kept")

    def test_a_zero_rate_is_out_and_the_least_positive_in(self):
        # line 88: numpy.nonzero(shearstrainrate), the rate of shearVelocity(), the largest
        # x-velocity of the fixed grains (python/sphere.py lines 4794-4808) with the bottom
        # layer at 0: a top layer at rest or moving backwards reads 0 and is out; any
        # positive velocity is nonzero and in
        s = series()
        rows = {t: np.nonzero(s["time"] == t)[0][0] for t in (6.5, 7.0, 7.5)}
        s["vx_top"][rows[6.5]] = 0.0
        s["vx_top"][rows[7.0]] = -1e-3
        s["vx_top"][rows[7.5]] = 5e-324
        self.assertEqual(cut_at(s, 6.5), "rate 0")
        self.assertEqual(cut_at(s, 7.0), "rate 0")
        self.assertEqual(cut_at(s, 7.5), "kept")

    def test_a_cycle_starts_at_its_first_sample_and_the_first_cycle_is_out(self):
        # the windows start at 6 s (lines 101-111): cycle 1's samples are out ("cycle"), its
        # window 1-3 s notwithstanding; a sample at t = 5 s exactly is cycle 2's first
        # (phase 0), outside its window; the initial state t = 0 is no sample (line 70,
        # readstep(i+1): files 1, 2, ...)
        s = series()
        self.assertEqual(cut_at(s, 2.0), "cycle")
        self.assertEqual(cut_at(s, 0.5), "outside 1-3 s, cycle")
        record = [r for r in original.fit_samples(s, PERIOD, TAU) if r["time"] == 5.0][0]
        self.assertEqual((record["cycle"], record["phase"], record["cut"]),
                         (2, 0.0, "outside 1-3 s"))
        self.assertEqual(cut_at(s, 2.0, first_cycle=1), "kept")
        with_zero = {k: np.concatenate([[v[0] if k != "time" else 0.0], v]) for k, v in s.items()}
        self.assertGreater(original.original_samples(with_zero, PERIOD)["time"][0], 0.0)

    def test_fit_samples_kept_are_the_fit(self):
        s = series()
        s["vx_top"][np.nonzero(s["time"] == 7.0)[0]] = -1e-3
        kept = [r["time"] for r in original.fit_samples(s, PERIOD, TAU) if r["cut"] == "kept"]
        fit = original.creep_fit(s, PERIOD, TAU)
        np.testing.assert_array_equal(kept, fit["time"])
        self.assertAlmostEqual(fit["n"], N_EXP, delta=1e-6)
        self.assertEqual(len(original.fit_samples(s, PERIOD, TAU)), CYCLES * 500)


class Grids(unittest.TestCase):
    def test_each_offset_is_every_second_row(self):
        """rows every 0.005 s (Table S1's): offset 0 the rows k even, offset 1 the rows k odd;
        each fit reads its own grid, and together they hold every row once"""
        k = np.arange(1, CYCLES * 1000 + 1)
        s = series(k * SPACING / 2)
        grid, stride = original.sample_grid(s["time"], PERIOD)
        self.assertEqual(stride, 2)
        np.testing.assert_array_equal(grid, k % 2)
        even = original.creep_fit(s, PERIOD, TAU, offset=0)["time"]
        odd = original.creep_fit(s, PERIOD, TAU, offset=1)["time"]
        np.testing.assert_array_equal(np.rint(even / (SPACING / 2)) % 2, 0)
        np.testing.assert_array_equal(np.rint(odd / (SPACING / 2)) % 2, 1)
        # the window (6, 8): rows k = 1201..1599 (1200 and 1600 stand at 6 and 8 s exactly:
        # out), 199 of them even, 200 odd
        cycle2 = [original.creep_fit(s, PERIOD, TAU, first_cycle=2, last_cycle=2, offset=j)["count"]
                  for j in (0, 1)]
        self.assertEqual(cycle2, [199, 200])
        both = np.sort([r["time"] for j in (0, 1)
                        for r in original.fit_samples(s, PERIOD, TAU, offset=j)])
        np.testing.assert_array_equal(both, s["time"])


class LeaveFastestOut(unittest.TestCase):
    def test_leaving_out_an_outlier_recovers_n(self):
        """the noise-free law with its fastest sample 50 times too fast: n off with it, n of
        the law once it (and then more) is left out; k = 0 .. 5 in order, counts falling"""
        f = np.linspace(0.1, 0.3, 60)
        r = 3.0 * f ** 6
        r[-1] *= 50.0
        rows = original.leave_fastest_out(f, r)
        self.assertEqual([x["left_out"] for x in rows], list(range(original.LEAVE_OUT + 1)))
        self.assertEqual([x["count"] for x in rows], [60 - k for k in range(6)])
        self.assertFalse(abs(rows[0]["n"] - 6.0) < 0.1)
        for x in rows[1:]:
            self.assertAlmostEqual(x["n"], 6.0, delta=1e-5)
        lo, hi, failed = original.leave_out_range(rows)
        self.assertAlmostEqual(lo, 6.0, delta=1e-5)
        self.assertAlmostEqual(hi, 6.0, delta=1e-5)
        self.assertEqual(failed, 0)

    def test_a_failed_fit_is_nan_and_counted(self):
        rows = [{"left_out": 0, "n": 4.0}, {"left_out": 1, "n": np.nan},
                {"left_out": 2, "n": 3.0}, {"left_out": 3, "n": 5.0}]
        self.assertEqual(original.leave_out_range(rows), (3.0, 5.0, 1))
        self.assertTrue(np.isnan(original.fit_rheology2(np.array([0.1, 0.2]),
                                                        np.array([1.0, 2.0]))["n"]))


if __name__ == "__main__":
    unittest.main()
