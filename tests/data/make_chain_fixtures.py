"""Fixtures for tests/tests/chain_vs_sympy.rs: SymPy KanesMethod on the planar relative-angle
chains (rigid links and point masses, n = 5 and 8), evaluated at random states. Run once with
SymPy (and mpmath, which SymPy needs) installed, from the repository root:

    python3 tests/data/make_chain_fixtures.py

It writes the model files tests/models/chain_{rigid,particle}_rel_{5,8}.al (the text of
kane-model/benches/scaling/chain_model.py, `--angles relative --plane planar`, with a comment
line saying so) and tests/data/chain_sympy.json: for each model 3 cases, each with the model
file's name and text, the values of the constants and states (by the model's upper-case names:
L1.., M1.., I1.. for rigid links, G, Q1.., U1..), and SymPy's mass matrix M, forcing f and
u' = M^-1 f there (M u' = f, KanesMethod's convention).

The SymPy model is sympy_chain.chain from the same folder as chain_model.py, the same chain:
frame i rotated from frame i-1 by Qi about axis 3, links along axis 1, rigid links' mass centres
at mid-link with central inertia 0, Ii, Ii (a rod along axis 1), point masses at the links' far ends, gravity
-G*N2>. The equations are evaluated at 30 significant digits (mpmath) and written as the
nearest doubles. Python is never needed to build or test the project.
"""
import json
import os
import random
import sys

import mpmath
import sympy as sm

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "kane-model", "benches", "scaling"))
from chain_model import chain_model  # noqa: E402
from sympy_chain import chain  # noqa: E402


def cases_for(kind, n, rng):
    name = f"chain_{kind}_rel_{n}.al"
    text = (f"% The planar relative-angle chain, {n} {kind} links: written by "
            f"tests/data/make_chain_fixtures.py\n% (kane-model/benches/scaling/chain_model.py "
            f"--links {n} --links-kind {kind}).\n"
            + chain_model(n, "relative", "planar", kind))
    with open(os.path.join(ROOT, "tests", "models", name), "w") as fh:
        fh.write(text)
    q, u, consts, km = chain(n, "relative", "planar", kind)
    plain = {s: sm.Symbol(str(s.func)) for s in list(q) + list(u)}
    names = sorted(consts) + [str(s.func) for s in list(q) + list(u)]
    args = [consts[k] for k in sorted(consts)] + [plain[s] for s in list(q) + list(u)]
    M = km.mass_matrix.xreplace(plain)
    f = km.forcing.xreplace(plain)
    fm = sm.lambdify(args, M, "mpmath")
    ff = sm.lambdify(args, f, "mpmath")
    out = []
    for _ in range(3):
        values = {}
        for k in sorted(consts):
            if k == "G":
                values[k] = 9.81
            elif k.startswith("I"):
                values[k] = rng.uniform(0.02, 0.4)
            else:
                values[k] = rng.uniform(0.5, 2.0)
        for s in q:
            values[str(s.func)] = rng.uniform(-3.0, 3.0)
        for s in u:
            values[str(s.func)] = rng.uniform(-2.0, 2.0)
        with mpmath.workdps(30):
            xs = [mpmath.mpf(values[k]) for k in names]
            Mv = mpmath.matrix(fm(*xs))
            fv = mpmath.matrix(ff(*xs))
            udot = mpmath.lu_solve(Mv, fv)
            out.append({
                "model": name,
                "text": text,
                "n": n,
                "values": values,
                "mass_matrix": [[float(Mv[i, j]) for j in range(n)] for i in range(n)],
                "forcing": [float(fv[i]) for i in range(n)],
                "udot": [float(udot[i]) for i in range(n)],
            })
    return out


def main():
    rng = random.Random(20260523)
    cases = []
    for kind in ("rigid", "particle"):
        for n in (5, 8):
            cases += cases_for(kind, n, rng)
    doc = {"source": "SymPy " + sm.__version__ + " KanesMethod, make_chain_fixtures.py", "cases": cases}
    with open(os.path.join(ROOT, "tests", "data", "chain_sympy.json"), "w") as fh:
        json.dump(doc, fh, indent=1)
        fh.write("\n")


if __name__ == "__main__":
    main()
