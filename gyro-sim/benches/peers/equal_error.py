"""Equal-error interpolation shared by the peer scripts."""
import numpy as np


def at_error(points, goal):
    """Time to reach error `goal` from (error, time) points in tolerance order, loose to tight:
    the first step across it, interpolated in log-log (NaN when no tolerance reaches it)."""
    pts = [(e, t) for e, t in points if e > 0]
    for (e0, t0), (e1, t1) in zip(pts, pts[1:]):
        if e1 <= goal < e0:
            f = (np.log(goal) - np.log(e0)) / (np.log(e1) - np.log(e0))
            return float(np.exp(np.log(t0) + f * (np.log(t1) - np.log(t0))))
    return float("nan")
