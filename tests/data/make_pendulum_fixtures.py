"""Fixtures for tests/tests/pendulum_vs_sympy.rs: SymPy KanesMethod on the planar n-link
pendulum (n = 1..5), evaluated at random states. Run once with SymPy installed:

    python3 tests/data/make_pendulum_fixtures.py > tests/data/n_link_pendulum_sympy.json

The model mirrors kane_model::models::n_link_pendulum: frame A_i rotated from N by the absolute
angle q_i about N.z, P_i = P_(i-1) + l_i A_i.x from a fixed pivot, particles m_i at P_i, gravity
-m_i g N.y, q_i' = u_i. Python is never needed to build or test the project.
"""
import json
import random

import sympy as sm
import sympy.physics.mechanics as me


def pendulum(n):
    q = me.dynamicsymbols(f"q1:{n + 1}")
    u = me.dynamicsymbols(f"u1:{n + 1}")
    m = sm.symbols(f"m1:{n + 1}")
    l = sm.symbols(f"l1:{n + 1}")
    g = sm.symbols("g")
    N = me.ReferenceFrame("N")
    P = me.Point("P0")
    P.set_vel(N, 0)
    particles, loads = [], []
    for i in range(n):
        A = N.orientnew(f"A{i + 1}", "Axis", [q[i], N.z])
        A.set_ang_vel(N, u[i] * N.z)
        Pi = P.locatenew(f"P{i + 1}", l[i] * A.x)
        Pi.v2pt_theory(P, N, A)
        particles.append(me.Particle(f"Pa{i + 1}", Pi, m[i]))
        loads.append((Pi, -m[i] * g * N.y))
        P = Pi
    kd = [q[i].diff() - u[i] for i in range(n)]
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(particles, loads)
    return q, u, m, l, g, km.mass_matrix, km.forcing


def main():
    rng = random.Random(20261122)
    cases = []
    for n in range(1, 6):
        q, u, m, l, g, M, f = pendulum(n)
        for _ in range(3):
            values = {}
            for s in q:
                values[s] = rng.uniform(-3.0, 3.0)
            for s in u:
                values[s] = rng.uniform(-2.0, 2.0)
            for s in list(m) + list(l):
                values[s] = rng.uniform(0.5, 2.0)
            values[g] = 9.81
            Mv = M.subs(values).evalf(30)
            fv = f.subs(values).evalf(30)
            names = {}
            for s, v in values.items():
                name = s.name if hasattr(s, "name") else str(s.func)
                names[name] = v
            cases.append({
                "n": n,
                "values": names,
                "mass_matrix": [[float(Mv[i, j]) for j in range(n)] for i in range(n)],
                "forcing": [float(fv[i]) for i in range(n)],
            })
    print(json.dumps({"source": "SymPy " + sm.__version__ + " KanesMethod", "cases": cases}, indent=1))


if __name__ == "__main__":
    main()
