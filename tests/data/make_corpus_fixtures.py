"""Fixtures for tests/tests/autolev_corpus.rs: SymPy's own parse of each corpus file, run, and
every quantity it defines evaluated at a random point. Run once with SymPy and
antlr4-python3-runtime 4.11 installed:

    python3 tests/data/make_corpus_fixtures.py > tests/data/autolev_corpus_sympy.json

Python is never needed to build or test the project.
"""
import contextlib
import io
import json
import random
import re
import sys
from pathlib import Path

import sympy as sm
from sympy.core.function import AppliedUndef
import sympy.physics.mechanics as me
from sympy.parsing.autolev import parse_autolev

HERE = Path(__file__).parent / "autolev-corpus"
FILES = sorted(HERE.glob("*.al")) + sorted((HERE / "pydy-example-repo").glob("*.al"))


def canonical(name):
    """The parser's speed u_q1_d of a Q{2}'' declaration is q1' (its kinematic equation says
    q1' = u_q1_d); one name gives both the same value at the sample point."""
    m = re.fullmatch(r"u_(\w+?)_d('*)", name)
    return m.group(1) + "'" + m.group(2) if m else name


def numeric_map(exprs, rng, values):
    """Random values for every free symbol and time-dependent function in exprs."""
    subs = {}
    for e in exprs:
        for f in e.atoms(sm.Derivative):
            base = f.expr.func.__name__
            order = sum(c for _, c in f.variable_count)
            name = canonical(base + "'" * order)
            values.setdefault(name, rng.uniform(0.3, 1.7))
            subs[f] = values[name]
    for e in exprs:
        for f in e.atoms(AppliedUndef):
            name = canonical(f.func.__name__)
            values.setdefault(name, rng.uniform(0.3, 1.7))
            subs[f] = values[name]
        for s in e.free_symbols:
            if s.name == "t":
                values.setdefault("t", rng.uniform(0.3, 1.7))
                subs[s] = values["t"]
            else:
                values.setdefault(s.name, rng.uniform(0.3, 1.7))
                subs[s] = values[s.name]
    return subs


def number(e, subs):
    v = complex(sm.N(e.subs(subs), 30))
    if abs(v.imag) > 1e-12:
        raise ValueError("complex")
    return v.real


def main():
    rng = random.Random(20261122)
    out = {}
    for path in FILES:
        rel = str(path.relative_to(HERE))
        code = parse_autolev(path.read_text(), include_numeric=False)
        # The parser (SymPy 1.14) declares derivatives as dynamicsymbols('q1_', 1): derivatives
        # of a function q1_(t) unrelated to q1(t), so its kinematic equations never mention q1'.
        # Naming them after the variables they differentiate restores the intended meaning.
        code = re.sub(
            r"dynamicsymbols\('([^']*)', (\d)\)",
            lambda m: "dynamicsymbols('" + " ".join(n.rstrip("_") for n in m.group(1).split()) + "', " + m.group(2) + ")",
            code,
        )
        ns = {}
        try:
            with contextlib.redirect_stdout(io.StringIO()):
                exec(code, ns)
        except Exception as e:  # the file's code fails in SymPy itself
            out[rel] = {"error": f"{type(e).__name__}: {e}"}
            continue
        values, scalars, matrices, vectors = {}, {}, {}, {}
        # Collect every quantity first, so that all sample values exist before any is evaluated.
        items = []
        for k, v in ns.items():
            if k.startswith("_") or k in ("m",):
                continue
            if isinstance(v, me.Vector) and v != 0:
                frame = v.args[0][1]
                try:
                    items.append((k, "vector", frame, list(v.to_matrix(frame))))
                except ValueError:  # terms in frames with no orientation between them
                    continue
            elif isinstance(v, sm.MatrixBase):
                items.append((k, "matrix", v.shape, list(v)))
            elif isinstance(v, sm.Expr) and not isinstance(v, (sm.Symbol, AppliedUndef)):
                items.append((k, "scalar", None, [v]))
        km = ns.get("kane")
        if km is not None:
            items.append(("__kane", "kane", km.mass_matrix.shape, list(km.mass_matrix) + list(km.forcing)))
        subs = {}
        for _, _, _, exprs in items:
            try:
                subs.update(numeric_map(exprs, rng, values))
            except Exception:
                pass
        # Sample a state that satisfies the motion constraints: solve them for the dependent speeds.
        if km is not None and getattr(km, "_udep", None) is not None and len(km._udep) > 0:
            cons = ns.get("velocity_constraints")
            dep = list(km._udep)
            if cons is not None:
                # The constraints are written in q1' (derivatives), the same quantities as u_q1_d.
                t = sm.Symbol("t")
                unknowns = {}
                for d in dep:
                    name = canonical(d.func.__name__)
                    base = name.rstrip("'")
                    q = [f for f in ns.values() if isinstance(f, AppliedUndef) and f.func.__name__ == base]
                    unknowns[name] = (d, sm.Derivative(q[0], t) if q else d)
                targets = [u for _, u in unknowns.values()]
                # Placeholders first: substituting q1(t) inside Derivative(q1(t), t) would erase it.
                holders = {u: sm.Dummy() for u in targets}
                known = {a: b for a, b in subs.items() if a not in dep and a not in targets}
                eqs = [sm.sympify(c).xreplace(holders).subs(known) for c in cons]
                sol = sm.solve(eqs, list(holders.values()), dict=True)[0]
                for name, (d, deriv) in unknowns.items():
                    values[name] = float(sol[holders[deriv]])
                    subs[d] = values[name]
                    subs[deriv] = values[name]
                # Accelerations too: the dependent speeds' derivatives from the constraints' rate.
                rates = [sm.sympify(c).diff(t) for c in cons]
                second = {name: sm.Derivative(deriv.args[0], (t, 2)) for name, (_, deriv) in unknowns.items()}
                acc_holders = {v: sm.Dummy() for v in second.values()}
                first = {u: subs[u] for u in targets}
                others = {}
                for f in set().union(*[r.atoms(sm.Derivative) for r in rates]):
                    if f in acc_holders or f in first:
                        continue
                    order = sum(c for _, c in f.variable_count)
                    name = canonical(f.expr.func.__name__ + "'" * order)
                    values.setdefault(name, rng.uniform(0.3, 1.7))
                    others[f] = values[name]
                eqs = [r.xreplace(acc_holders).xreplace(holders).xreplace({holders[u]: first[u] for u in targets}) for r in rates]
                eqs = [e.xreplace({k: v for k, v in others.items()}).subs(known) for e in eqs]
                asol = sm.solve(eqs, list(acc_holders.values()), dict=True)[0]
                for name, (d, deriv) in unknowns.items():
                    acc_name = name + "'"
                    values[acc_name] = float(asol[acc_holders[second[name]]])
                    for f in list(subs) + [sm.Derivative(d, t)]:
                        if isinstance(f, sm.Derivative) and canonical(f.expr.func.__name__ + "'" * sum(c for _, c in f.variable_count)) == acc_name:
                            subs[f] = values[acc_name]
                    subs[sm.Derivative(d, t)] = values[acc_name]
        for k, kind, extra, exprs in items:
            try:
                nums = [number(e, subs) for e in exprs]
            except Exception:
                continue
            if kind == "vector":
                vectors[k] = {"frame": extra.name.upper(), "components": nums}
            elif kind == "matrix":
                r, c = extra
                matrices[k] = [nums[i * c:(i + 1) * c] for i in range(r)]
            elif kind == "scalar":
                scalars[k] = nums[0]
        entry = {"values": values, "scalars": scalars, "matrices": matrices, "vectors": vectors}
        if km is not None:
            n = km.mass_matrix.shape[0]
            mm = [number(x, subs) for x in km.mass_matrix]
            entry["kane"] = {
                "mass_matrix": [mm[i * n:(i + 1) * n] for i in range(n)],
                "forcing": [number(x, subs) for x in km.forcing],
            }
        out[rel] = entry
    json.dump({"source": "SymPy " + sm.__version__ + " parse_autolev", "files": out}, sys.stdout, indent=1, sort_keys=True)


if __name__ == "__main__":
    main()
