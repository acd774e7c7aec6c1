"""Reference trajectories for the paper's trials, independent of this project's code: the
gimbal's hand-derived equations (tests/tests/gimbal_hand_derivation.rs) integrated by SciPy's
DOP853 at rtol = atol = 1e-13. Run once with SciPy installed:

    python3 gyro-sim/tests/data/make_trial_references.py

Writes gimbal_trial{1,2,3}.csv and checks itself against the shared script-case reference.
Columns t, q1, q2, q3 (rad), u1, u2, u3 (rad/s), aP (m/s^2).
"""
import csv
from math import cos, sin, sqrt
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

HERE = Path(__file__).parent
M1, M2, M3, H1, H2, H3, L, W = 2.0, 2.0, 50.0, 0.6, 0.5, 0.4, 0.3, 0.025
I1 = 2 / 3 * M1 * (H1 * W - W**2)
J1 = 2 / 3 * M2 * (H2 * W - W**2)
J2 = M2 * H2**2 / 6 - M2 * (H2 - W) ** 2 / 6
K1 = M3 * L**2 / 2
K2 = M3 * L**2 / 4 + M3 * H3**2 / 12


def accel(y, Y, Z):
    q1, q2, q3, u1, u2, u3 = y
    s, c = sin(q2), cos(q2)
    m = np.array([[I1 + J1 * c * c + J2 * s * s + K1 * c * c + K2 * s * s, 0, K1 * c], [0, J1 + K2, 0], [K1 * c, 0, K1]])
    f = np.array([
        -Y + 2 * (J1 + K1 - J2 - K2) * s * c * u1 * u2 + K1 * s * u2 * u3,
        -Z + (J2 + K2 - J1 - K1) * s * c * u1 * u1 - K1 * s * u1 * u3,
        K1 * s * u1 * u2,
    ])
    return np.linalg.solve(m, f)


def rhs(t, y, Y, Z):
    return np.concatenate([y[3:], accel(y, Y, Z)])


def a_p(y, Y, Z):
    """|a_P| for P = L d1, from the hand kinematics in C's basis."""
    q1, q2, q3, u1, u2, u3 = y
    d1, d2, d3 = accel(y, Y, Z)
    s, c = sin(q2), cos(q2)
    wc = np.array([-u2, -u1 * c, -u1 * s])
    wd = np.array([-u2, -u1 * c - u3, -u1 * s])
    wd_dot = np.array([-d2, -d1 * c + u1 * s * u2 - d3, -d1 * s - u1 * c * u2])
    alpha = wd_dot + np.cross(wc, wd)
    r = L * np.array([cos(q3), 0.0, sin(q3)])
    a = np.cross(alpha, r) + np.cross(wd, np.cross(wd, r))
    return sqrt(a @ a)


def trajectory(Y, Z, U3):
    t = np.arange(101) * 0.05
    sol = solve_ivp(rhs, (0, 5), [0, 0, 0, 0, 0, U3], method="DOP853", t_eval=t, rtol=1e-13, atol=1e-13, args=(Y, Z))
    return [[ti] + list(sol.y[:, k]) + [a_p(sol.y[:, k], Y, Z)] for k, ti in enumerate(sol.t)]


def write(name, rows):
    with open(HERE / name, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "q1", "q2", "q3", "u1", "u2", "u3", "aP"])
        for r in rows:
            w.writerow([repr(float(x)) for x in r])


def main():
    script = trajectory(0.0, 10.0, 10.0)
    shared = list(csv.reader(open(HERE / "gimbal_script_case.csv")))[1:]
    worst = max(abs(a - float(b)) / max(abs(float(b)), 1) for r, s in zip(script, shared) for a, b in zip(r[1:], s[1:]))
    print("script case against the shared reference:", worst)
    assert worst < 1e-9
    write("gimbal_trial1.csv", trajectory(10.0, 0.0, 10.0))
    write("gimbal_trial2.csv", trajectory(10.0, 10.0, 10.0))
    write("gimbal_trial3.csv", trajectory(10.0, 10.0, 100.0))


if __name__ == "__main__":
    main()
