"""The Whipple bicycle file against the benchmark (Meijaard, Papadopoulos, Ruina and Schwab 2007),
through `kane linearize` (not needed by build or tests; the Rust test whipple_bicycle.rs holds the
same to 1e-12 and 1e-8):

    python3 kane-model/benches/bicycle/against_benchmark.py [target/release/kane]

Prints the largest relative difference of the lean and steer rows of A (roll Q2, steer Q5 and
their rates) from the benchmark's at 0..10 m/s, as SymPy's bicycle test states them, and the
weave and capsize speeds found by bisection on the Routh-Hurwitz conditions of that block
(weave: a3 a2 a1 - a1^2 - a3^2 a0 = 0; capsize: a0 = det A = 0).
"""
import json
import os
import subprocess
import sys

KANE = sys.argv[1] if len(sys.argv) > 1 else "target/release/kane"
FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "models", "whipple_bicycle.al")


def benchmark_rows(v):
    return [[9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245, -0.105522449805691 * v, -0.330515398992311 * v],
            [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407, 3.67680523332152 * v, -3.08486552743311 * v]]


def block(v):
    out = subprocess.run([KANE, "linearize", FILE, "--json", "--set", f"V={v!r}"], capture_output=True, text=True, check=True)
    d = json.loads(out.stdout)
    idx = [d["states"].index(n) for n in ("Q2", "Q5", "U2", "U5")]
    return [[d["A"][i][j] for j in idx] for i in idx]


def charpoly(a):
    """s^4 + c1 s^3 + c2 s^2 + c3 s + c4 (Faddeev-LeVerrier)."""
    mul = lambda x, y: [[sum(x[i][k] * y[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    m, c = [[0.0] * 4 for _ in range(4)], [1.0]
    for k in range(1, 5):
        am = mul(a, m)
        m = [[am[i][j] + (c[-1] if i == j else 0.0) for j in range(4)] for i in range(4)]
        c.append(-sum(mul(a, m)[i][i] for i in range(4)) / k)
    return c


def bisect(f, lo, hi):
    f_lo = f(lo)
    for _ in range(45):
        mid = 0.5 * (lo + hi)
        if (f(mid) > 0) == (f_lo > 0):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


worst = 0.0
for v in range(11):
    a, want = block(float(v)), benchmark_rows(float(v))
    worst = max(worst, max(abs(a[2 + i][j] - want[i][j]) / max(1.0, abs(want[i][j])) for i in range(2) for j in range(4)))
print(f"lean and steer rows of A, v = 0..10 m/s: largest relative difference {worst:.2e}")


def weave(v):
    _, a3, a2, a1, a0 = charpoly(block(v))
    return a3 * a2 * a1 - a1 * a1 - a3 * a3 * a0


print(f"weave speed   {bisect(weave, 3.0, 5.0):.10f} m/s (benchmark 4.29238254)")
print(f"capsize speed {bisect(lambda v: charpoly(block(v))[4], 5.0, 7.0):.10f} m/s (benchmark 6.02426202)")
