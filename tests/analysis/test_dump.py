"""porewater_analysis.dump.read_dump on a dump written out of id order, as LAMMPS writes one
from several ranks or after the grains were sorted in memory"""
import os
import tempfile
import unittest

import numpy as np

from porewater_analysis.dump import read_dump

DUMP = """ITEM: TIMESTEP
100
ITEM: NUMBER OF ATOMS
3
ITEM: BOX BOUNDS pp pp fm
0 0.26
-0.5 0.5
0 0.3
ITEM: ATOMS id type radius x y z
7 1 0.01 0.1 0.2 0.3
2 1 0.011 0.4 0.5 0.6
5 1 0.012 0.7 0.8 0.9
"""


class ReadDump(unittest.TestCase):
    def setUp(self):
        fd, self.path = tempfile.mkstemp(suffix=".dump")
        with os.fdopen(fd, "w") as f:
            f.write(DUMP)

    def tearDown(self):
        os.remove(self.path)

    def test_box_lengths(self):
        length, _ = read_dump(self.path)
        np.testing.assert_array_equal(length, [0.26, 1.0, 0.3])

    def test_rows_in_id_order_with_their_columns(self):
        _, c = read_dump(self.path)
        np.testing.assert_array_equal(c["id"], [2, 5, 7])
        np.testing.assert_array_equal(c["x"], [0.4, 0.7, 0.1])
        np.testing.assert_array_equal(c["radius"], [0.011, 0.012, 0.01])


if __name__ == "__main__":
    unittest.main()
