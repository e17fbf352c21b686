"""porewater_analysis.landings on a synthetic Table S1 (5 s cycles, rows every 0.005 s with
its drift) whose landings are known by construction: after each landing the count swings
row to row, so each grid of every second row finds another minimum; a deeper minimum outside
the windows and a landing the rows do not cover wholly are left out; the data file's own
minimum at the same landing beside it. And swing's period and amplitude."""
import unittest

import numpy as np

from porewater_analysis import landings

PERIOD = 5.0
ROW = 0.0050018258894     # s: Table S1's rows (k nout dt), drifting from k 0.005
ROWS = 2998               # to 14.9955 s: landing 3's window (14.25-15.75 s) not covered
# (row k, count): the every-row minimum of each landing on an odd k (grid offset 1), the
# least of the even k (offset 0, the original's samples) elsewhere in the window
LANDING_ROWS = {1: {"odd": (985, 0.065), "even": (956, 0.121)},
                2: {"odd": (1993, 0.049), "even": (2042, 0.096)}}
OUTSIDE = (500, 0.001)    # 2.5 s: the creep, a minimum in no window
DATA_MIN = {1: (4.94, 0.039), 2: (10.03, 0.041), 3: (15.06, 0.046)}


def synthetic():
    k = np.arange(1, ROWS + 1)
    t = k * ROW
    z = np.full(len(k), 3.0)
    for landing, rows in LANDING_ROWS.items():
        # the swing: every row within 0.1 s of the landing low on one grid, high on the other
        near = np.abs(t - landing * PERIOD) < 0.1
        z[near & (k % 2 == 1)] = 0.5
        z[near & (k % 2 == 0)] = 2.5
        for kk, value in rows.values():
            z[kk - 1] = value
    z[OUTSIDE[0] - 1] = OUTSIDE[1]
    series = {"time": t, "coordination_original": z}
    td = np.round(np.arange(1, 2001) * 0.01, 2)        # the data file: 0.01 .. 20 s
    zd = np.full(len(td), 3.0)
    zd[np.nonzero(td == 7.5)[0]] = 0.0                 # outside the windows
    for landing, (when, value) in DATA_MIN.items():
        zd[np.nonzero(td == when)[0]] = value
    return series, (td, zd), k


class Landings(unittest.TestCase):
    def setUp(self):
        self.series, self.data, self.k = synthetic()
        self.rows = landings.landings(self.series, PERIOD, self.data)

    def test_the_landings_the_rows_cover(self):
        self.assertEqual([r["landing"] for r in self.rows], [1, 2])
        for r in self.rows:
            k = r["landing"]
            self.assertEqual(r["window"], ((k - landings.HALF_WIDTH) * PERIOD,
                                           (k + landings.HALF_WIDTH) * PERIOD))
            self.assertEqual(r["stride"], 2)

    def test_every_row_and_each_grid(self):
        t = self.series["time"]
        for r in self.rows:
            odd_k, odd_z = LANDING_ROWS[r["landing"]]["odd"]
            even_k, even_z = LANDING_ROWS[r["landing"]]["even"]
            self.assertEqual((r["every_row"]["min"], r["every_row"]["time"]), (odd_z, t[odd_k - 1]))
            # offset 0: k even, the original's samples; offset 1: k odd
            self.assertEqual((r["grid"][0]["min"], r["grid"][0]["time"]), (even_z, t[even_k - 1]))
            self.assertEqual((r["grid"][1]["min"], r["grid"][1]["time"]), (odd_z, t[odd_k - 1]))
            phase = (t[odd_k - 1] / PERIOD) % 1.0
            self.assertAlmostEqual(r["every_row"]["phase"], phase, places=12)
            self.assertAlmostEqual(r["every_row"]["after_min_n"], (phase - 0.75) % 1.0, places=12)

    def test_the_data_files_same_landing(self):
        for r in self.rows:
            when, value = DATA_MIN[r["landing"]]
            self.assertEqual((r["data_file"]["min"], r["data_file"]["time"]), (value, when))
            self.assertAlmostEqual(r["data_file"]["after_min_n"], ((when / PERIOD) % 1 - 0.75) % 1,
                                   places=9)
        short = (self.data[0][self.data[0] < 7.0], self.data[1][self.data[0] < 7.0])
        rows = landings.landings(self.series, PERIOD, short)
        self.assertIsNotNone(rows[0]["data_file"])
        self.assertIsNone(rows[1]["data_file"])      # the data file does not cover landing 2
        self.assertIsNone(landings.landings(self.series, PERIOD)[0]["data_file"])

    def test_windows_cover_wholly(self):
        t = np.arange(1, 1501) * 0.01                    # to 15.00 s
        self.assertEqual([k for k, _, _ in landings.windows(t, PERIOD)], [1, 2])
        self.assertEqual([k for k, _, _ in landings.windows(t, PERIOD, 0.0)], [1, 2, 3])
        late = t[t > 4.5]                                # landing 1's window opens at 4.25 s
        self.assertEqual([k for k, _, _ in landings.windows(late, PERIOD)], [2])

    def test_a_series_without_the_count(self):
        self.assertEqual(landings.landings({"time": self.series["time"]}, PERIOD), [])


class Swing(unittest.TestCase):
    def test_a_row_to_row_swing_on_a_trend(self):
        """+-1 every other row over a quadratic: period two rows, amplitude 1 (the trend's
        fit takes a little of the swing: within 5 %)"""
        t = np.arange(40) * 0.005
        x = 3.0 + 0.2 * t - 4.0 * t ** 2 + np.where(np.arange(40) % 2 == 0, 1.0, -1.0)
        s = landings.swing(t, x)
        self.assertAlmostEqual(s["period_fft"], 0.01, places=9)
        self.assertAlmostEqual(s["period_crossings"], 0.01, places=9)
        self.assertAlmostEqual(s["amplitude"], 1.0, delta=0.05)

    def test_a_slower_sinusoid(self):
        """period 0.05 s (10 rows) over 1 s on a line: both periods 0.05 s; the amplitude
        half the 10-90 % span of the sine's own samples (the line's fit takes a little of
        it: within 5 %)"""
        t = np.arange(200) * 0.005
        sine = 0.7 * np.sin(2 * np.pi * t / 0.05 + 0.3)
        s = landings.swing(t, sine + 5.0 * t, degree=1)
        self.assertAlmostEqual(s["period_fft"], 0.05, places=6)
        self.assertAlmostEqual(s["period_crossings"], 0.05, delta=0.001)
        lo, hi = np.percentile(sine, [10, 90])
        self.assertAlmostEqual(s["amplitude"] / (0.5 * (hi - lo)), 1.0, delta=0.05)

    def test_after_landing(self):
        t = np.arange(1, 2001) * 0.005
        m = landings.after_landing(t, 4.93, PERIOD)
        self.assertEqual(m.sum(), 20)
        self.assertGreaterEqual(t[m][0], 4.93)


if __name__ == "__main__":
    unittest.main()
