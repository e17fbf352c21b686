"""porewater_analysis.timeseries.nearest_rows: the row nearest each time, on rows as a run
writes them (a cadence that drifts from the times asked for), before the first and past the last"""
import unittest

import numpy as np

from porewater_analysis.timeseries import nearest_rows


class NearestRows(unittest.TestCase):
    time = np.array([0.0, 0.0101, 0.0203, 0.0304, 0.0406])

    def test_each_time_gets_the_row_nearest_it(self):
        at = np.array([0.01, 0.02, 0.03, 0.04, 0.0150, 0.0154])
        expected = [int(np.argmin(abs(self.time - t))) for t in at]
        self.assertEqual(list(nearest_rows(self.time, at)), expected)
        self.assertEqual(expected, [1, 2, 3, 4, 1, 2])

    def test_times_outside_the_rows_get_the_first_or_last_row(self):
        self.assertEqual(list(nearest_rows(self.time, [-1.0, 0.0, 0.0406, 5.0])), [0, 0, 4, 4])

    def test_a_single_time_gives_a_single_row(self):
        self.assertEqual(int(nearest_rows(self.time, 0.03)), 3)


if __name__ == "__main__":
    unittest.main()
