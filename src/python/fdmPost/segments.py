"""The segments of a run joined on time.

A run continued from a checkpoint at time T writes its record of T again,
so the records kept of the earlier segments are those before the later
segment's first, and a checkpoint of time T keeps the records up to T.
"""

import numpy as np

# Relative tolerance on times written with at least 12 digits
TIME_TOLERANCE = 1e-12


def up_to(times, time):
    """Mask of the records at times up to `time`."""
    return np.asarray(times) <= time * (1 + TIME_TOLERANCE)


def before(times, later_times):
    """Mask of the records before the first of a later segment's (all of
    them when the later segment has none)."""
    times = np.asarray(times)
    if not len(later_times):
        return np.ones(len(times), bool)
    return times < later_times[0] * (1 - TIME_TOLERANCE)
