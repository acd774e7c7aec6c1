"""The peers' copies of the equations, written from the hand derivations (not from gyro-sim's
generated code): the paper's gimbal (tests/tests/gimbal_hand_derivation.rs) and the heavy
symmetric top in Euler parameters and body rates (the EJS convention of
../shared/references/README.md, copied in gyro-sim/tests/data/ejs/PROVENANCE.md): space z up,
M = g = 1, rotor centred d = 1 along body z, I1 = I2 = 151/125, I3 = 2/5 about the support,
quaternion (qw, qx, qy, qz) body -> space, qdot = q (0, omega) / 2. The same top spin-aware
(top_axle) is kane-model/models/heavy_top_axle.al written out by hand.
"""
import heyoka as hy

M1, M2, M3, H1, H2, H3, L, W = 2.0, 2.0, 50.0, 0.6, 0.5, 0.4, 0.3, 0.025


def gimbal(num=float):
    """(state variable, rate) pairs of the gimbal; parameters Y = par[0], Z = par[1]."""
    i1 = num(2) / 3 * M1 * (num(H1) * num(W) - num(W) ** 2)
    j1 = num(2) / 3 * M2 * (num(H2) * num(W) - num(W) ** 2)
    j2 = M2 * num(H2) ** 2 / 6 - M2 * (num(H2) - num(W)) ** 2 / 6
    k1 = M3 * num(L) ** 2 / 2
    k2 = M3 * num(L) ** 2 / 4 + M3 * num(H3) ** 2 / 12
    q1, q2, q3, u1, u2, u3 = hy.make_vars("q1", "q2", "q3", "u1", "u2", "u3")
    y, z = hy.par[0], hy.par[1]
    s, c = hy.sin(q2), hy.cos(q2)
    a = i1 + j1 * c * c + j2 * s * s + k1 * c * c + k2 * s * s
    b = k1 * c
    f1 = -y + 2 * (j1 + k1 - j2 - k2) * s * c * u1 * u2 + k1 * s * u2 * u3
    f2 = -z + (j2 + k2 - j1 - k1) * s * c * u1 * u1 - k1 * s * u1 * u3
    f3 = k1 * s * u1 * u2
    det = a * k1 - b * b
    return [(q1, u1), (q2, u2), (q3, u3), (u1, (k1 * f1 - b * f3) / det), (u2, f2 / (j1 + k2)), (u3, (a * f3 - b * f1) / det)]


def top(num=float):
    """(state variable, rate) pairs of the heavy top: qw, qx, qy, qz, w1, w2, w3."""
    qw, qx, qy, qz, w1, w2, w3 = hy.make_vars("qw", "qx", "qy", "qz", "w1", "w2", "w3")
    it, ia, half = num(151) / 125, num(2) / 5, num(1) / 2
    nx = 2 * (qx * qz - qw * qy)
    ny = 2 * (qy * qz + qw * qx)
    return [
        (qw, -half * (qx * w1 + qy * w2 + qz * w3)),
        (qx, half * (qw * w1 + qy * w3 - qz * w2)),
        (qy, half * (qw * w2 + qz * w1 - qx * w3)),
        (qz, half * (qw * w3 + qx * w2 - qy * w1)),
        (w1, ((it - ia) * w2 * w3 + ny) / it),
        (w2, ((ia - it) * w3 * w1 - nx) / it),
        (w3, 0 * w1),
    ]


def top_axle(num=float):
    """(state variable, rate) pairs of the spin-aware heavy top, the equations of
    kane-model/models/heavy_top_axle.al (model heavy_top_axle): qw, qx, qy, qz are the Euler
    parameters of the axle frame A (E4, E1, E2, E3), which turns with the axle but not with the
    spin, so its angular velocity is (w1, w2, 0) in A; w3 is the rotor's whole rate about the
    axle. About the support H = (It w1, It w2, Ia w3) in A, dH/dt = H' + (w1, w2, 0) x H, and
    gravity's moment is (ny, -nx, 0) with (nx, ny) = N3 along A1, A2:
        It w1' = ny - Ia w2 w3,   It w2' = Ia w1 w3 - nx,   Ia w3' = 0.
    The spin angle (PSI' = w3) is read by no equation and by none of the outputs compared, so it
    is left out, as gyro-sim leaves it out of the integration when no output needs it."""
    qw, qx, qy, qz, w1, w2, w3 = hy.make_vars("qw", "qx", "qy", "qz", "w1", "w2", "w3")
    it, ia, half = num(151) / 125, num(2) / 5, num(1) / 2
    nx = 2 * (qx * qz - qw * qy)
    ny = 2 * (qy * qz + qw * qx)
    return [
        (qw, -half * (qx * w1 + qy * w2)),
        (qx, half * (qw * w1 - qz * w2)),
        (qy, half * (qw * w2 + qz * w1)),
        (qz, half * (qx * w2 - qy * w1)),
        (w1, (ny - ia * w2 * w3) / it),
        (w2, (ia * w1 * w3 - nx) / it),
        (w3, 0 * w1),
    ]


def axle(q):
    """The body z axis in space from rows of (qw, qx, qy, qz)."""
    qw, qx, qy, qz = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    import numpy as np

    return np.stack([2 * (qx * qz + qw * qy), 2 * (qy * qz - qw * qx), qw * qw - qx * qx - qy * qy + qz * qz], axis=1)
