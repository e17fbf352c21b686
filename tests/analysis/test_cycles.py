"""porewater_analysis.cycles (this package's estimators) on the synthetic series of
test_original.py with a slow creep (1e-5 m/s) and a slip of 2 m/s over phases 0.7-0.8 known
by construction: the suction of the slip, in the bed's mean and right under the plate (the
p_top_layer column)"""
import unittest

import numpy as np

from porewater_analysis.cycles import factor_metrics
from test_original import AMP, CYCLES, PERIOD, ROWS, SLIP, TAU, synthetic

INSIDE, OUTSIDE = 750, 500         # rows within a cycle: in the slip, in the creep before it


class SlipSuction(unittest.TestCase):
    def setUp(self):
        self.series, k = synthetic()
        self.row = k % ROWS
        phase = self.row / ROWS
        vx = np.where((phase >= 0.7) & (phase < 0.8), SLIP, 1e-5)
        self.series.update(vx_top=vx, x_top=np.cumsum(vx) * (PERIOD / ROWS))

    def metrics(self):
        return factor_metrics(self.series, CYCLES, period=PERIOD, tau=TAU, amp=AMP)

    def test_under_the_plate_only_with_its_column(self):
        for r in self.metrics().values():
            self.assertNotIn("suction_top", r)

    def test_least_pressure_under_the_plate_within_the_slip(self):
        p_top = self.series["p_top"]
        layer = p_top.copy()
        layer[self.row == INSIDE] -= 0.3 * AMP       # counted: inside the slip
        layer[self.row == OUTSIDE] -= 0.9 * AMP      # not: before it
        self.series["p_top_layer"] = layer
        self.series["p_mean"] = p_top - 0.1 * AMP    # the bed's mean: 0.1 A under p_top
        slipped = [r for r in self.metrics().values() if "onset" in r]
        self.assertEqual(len(slipped), CYCLES)
        for r in slipped:
            self.assertLess(r["onset"], INSIDE / ROWS)
            self.assertGreater(r["end"], INSIDE / ROWS)
            self.assertGreater(r["onset"], OUTSIDE / ROWS)
            self.assertAlmostEqual(r["suction_top"], -0.3, places=12)
            self.assertAlmostEqual(r["suction"], -0.1, places=12)


if __name__ == "__main__":
    unittest.main()
