"""Equal-error comparisons: the time a renderer needs to reach an error, from its sweep."""

import math


def time_to_reach(points, error):
    """Log-log interpolation of (time, error) points, error falling with time: the time at
    which the error would be `error`; None outside the points."""
    points = sorted(points)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e0 >= error >= e1 and e0 > e1:
            s = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))
    return None
