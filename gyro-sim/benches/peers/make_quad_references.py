"""Quadruple-precision references for the equal-error comparisons, by heyoka in real128 at
tolerance 1e-32 (Taylor method), from the equations in models.py:

- gyro-sim/tests/data/gimbal_trial3_quad.csv: Trial 3 (Y = Z = 10 N m, U3 = 100 rad/s), every
  0.05 s to t = 5; columns t, q1, q2, q3, u1, u2, u3 (rad, rad/s);
- gyro-sim/tests/data/ejs/top_fast_quad.csv: the fast top (60 deg, spin 1000 rad/s, at rest),
  every 0.01 s to t = 10; columns t, qw, qx, qy, qz, w1, w2, w3.

Each is checked against a second run at tolerance 1e-30 (the difference printed), and Trial 3
against gyro-sim/tests/data/gimbal_trial3.csv (SciPy DOP853 at 1e-13). Not needed by the build
or the tests. Run once from the repository root: python3 gyro-sim/benches/peers/make_quad_references.py
"""
import csv
import sys
from pathlib import Path

import heyoka as hy
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import models  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
R = hy.real128


def run(system, y0, pars, grid, tol):
    ta = hy.taylor_adaptive(system, np.array(y0, dtype=R), tol=R(tol), pars=np.array(pars, dtype=R), fp_type=R)
    out = ta.propagate_grid(np.array(grid, dtype=R))
    return out[-1]


def write(path, header, grid, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for t, r in zip(grid, rows):
            w.writerow([repr(float(t))] + [str(x) for x in r])
    print("wrote", path)


def main():
    grid3 = [R(k) / 20 for k in range(101)]
    y3 = [0, 0, 0, 0, 0, 100]
    a = run(models.gimbal(R), y3, [10, 10], grid3, 1e-32)
    b = run(models.gimbal(R), y3, [10, 10], grid3, 1e-30)
    print("trial 3: tol 1e-32 vs 1e-30:", float(np.max(np.abs(a - b))))
    old = np.loadtxt(ROOT / "gyro-sim/tests/data/gimbal_trial3.csv", delimiter=",", skiprows=1)[:, 1:7]
    print("trial 3: against SciPy DOP853 1e-13:", float(np.max(np.abs(a.astype(float) - old))))
    write(ROOT / "gyro-sim/tests/data/gimbal_trial3_quad.csv", ["t", "q1", "q2", "q3", "u1", "u2", "u3"], grid3, a)
    th = R("1.047197551196597746154214461093167628")  # pi/3
    gridf = [R(k) / 100 for k in range(1001)]
    yf = [np.cos(th / 2), np.sin(th / 2), R(0), R(0), R(0), R(0), R(1000)]
    a = run(models.top(R), yf, [], gridf, 1e-32)
    b = run(models.top(R), yf, [], gridf, 1e-30)
    print("fast top: tol 1e-32 vs 1e-30:", float(np.max(np.abs(a - b))))
    write(ROOT / "gyro-sim/tests/data/ejs/top_fast_quad.csv", ["t", "qw", "qx", "qy", "qz", "w1", "w2", "w3"], gridf, a)


if __name__ == "__main__":
    main()
