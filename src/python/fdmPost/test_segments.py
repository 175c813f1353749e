"""Unit tests of fdmPost.segments: a later segment restarted at 0.3 (its
first record written again) keeps the earlier records before it only; a
checkpoint at 0.3 keeps the records up to it, times written with 12 digits
included; an empty later segment keeps every earlier record."""

import unittest

import numpy as np

from fdmPost import segments


class Segments(unittest.TestCase):
    def test_before_a_restarted_segment(self):
        earlier = np.array([0.0, 0.16, 0.3, 0.32])
        later = np.array([0.3 * (1 + 1e-14), 0.46])
        np.testing.assert_array_equal(segments.before(earlier, later),
                                      [True, True, False, False])
        np.testing.assert_array_equal(segments.before(earlier, []),
                                      [True] * 4)

    def test_up_to_a_checkpoint(self):
        times = np.array([0.0, 0.16, 0.32000000000001, 0.48])
        np.testing.assert_array_equal(segments.up_to(times, 0.32),
                                      [True, True, True, False])


if __name__ == "__main__":
    unittest.main()
