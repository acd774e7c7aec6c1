"""SymPy's KanesMethod on the chains of chain_model.py, timed: the derivation-scaling baseline.

    python3 sympy_chain.py [--variants V,V,...] [--ns 5,10,20,40,80,200] [--timeout 300]
                           [--out sympy_results.csv]

Variants are named PLANE-ANGLES-KIND, e.g. planar-relative-particle, planar-absolute-particle,
planar-relative-rigid, spatial-relative-rigid (default: the three planar ones the results file
holds). Every (variant, n) runs in its own Python process, killed at the timeout (default 5 min);
once a variant's case is over the timeout its larger n are not run. Writes a CSV (default
sympy_results.csv beside this script, with the date, machine, SymPy version and the load
average in # comments):

    variant, n, derive_s, cse_ops, trig_calls, cse_s, derive_cpu_s

* derive_s: building the frames, points, bodies and loads, and KanesMethod.kanes_equations
  (mass matrix and forcing of the dynamic equations, M u' = f), wall-clock seconds.
* cse_ops: after replacing q_i(t), u_i(t) by plain symbols, `sympy.cse` on the mass matrix
  (all n x n entries) and the forcing together; the operations of the replacements and reduced
  expressions as `sympy.count_ops(..., visual=False)` counts them (+ - * / and powers, and each
  sin/cos call counts one).
* trig_calls: the sin/cos/tan calls among those operations.
* cse_s: the seconds `sympy.cse` took (not in derive_s).
* derive_cpu_s: the derivation's CPU seconds (process time), which other jobs on a shared
  machine disturb less than the wall clock; the timeout is on the wall clock.

A case over the timeout is written "over 5 min" (in cse_ops when the derivation finished in time
but CSE did not). `python3 sympy_chain.py --one VARIANT N` runs one case and prints its lines.
The model (names, signs, mass centres, gravity -G N.y) is the one chain_model.py writes; the
function `chain` is also used by tests/data/make_chain_fixtures.py.
"""
import argparse
import datetime
import os
import platform
import subprocess
import sys
import tempfile
import time

import sympy as sm
import sympy.physics.mechanics as me

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_VARIANTS = ["planar-relative-particle", "planar-absolute-particle", "planar-relative-rigid"]


def chain(n, angles="relative", plane="planar", kind="particle"):
    """The chain's KanesMethod, after kanes_equations: (q, u, constants, km).

    constants maps each constant's name (L1, M1, I1, K1, G) to its symbol; q and u are the
    dynamicsymbols Q1..Qn, U1..Un.
    """
    rigid = kind == "rigid"
    spatial = plane == "spatial"
    q = me.dynamicsymbols(f"Q1:{n + 1}")
    u = me.dynamicsymbols(f"U1:{n + 1}")
    L = sm.symbols(f"L1:{n + 1}")
    M = sm.symbols(f"M1:{n + 1}")
    I = sm.symbols(f"I1:{n + 1}")
    K = sm.symbols(f"K1:{n + 1}")
    g = sm.symbols("G")
    consts = {s.name: s for s in list(L) + list(M) + [g]}
    if rigid:
        consts.update({s.name: s for s in I})
        if spatial:
            consts.update({s.name: s for s in K})
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    parent, joint = N, O
    bodies, loads = [], []
    for i in range(n):
        axis_no = (3 if i % 2 == 0 else 1) if spatial else 3
        ref = N if angles == "absolute" else parent
        axis = ref.z if axis_no == 3 else ref.x
        name = f"{'B' if rigid else 'F'}{i + 1}"
        Fi = ref.orientnew(name, "Axis", [q[i], axis])
        Fi.set_ang_vel(ref, u[i] * axis)
        d = Fi.y if spatial else Fi.x
        if rigid:
            C = joint.locatenew(f"{name}O", L[i] / 2 * d)
            C.v2pt_theory(joint, N, Fi)
            Ii = me.inertia(Fi, I[i], K[i], I[i]) if spatial else me.inertia(Fi, 0, I[i], I[i])
            bodies.append(me.RigidBody(name, C, Fi, M[i], (Ii, C)))
            loads.append((C, -M[i] * g * N.y))
            nxt = joint.locatenew(f"J{i + 1}", L[i] * d)
            nxt.v2pt_theory(joint, N, Fi)
        else:
            nxt = joint.locatenew(f"P{i + 1}", L[i] * d)
            nxt.v2pt_theory(joint, N, Fi)
            bodies.append(me.Particle(f"P{i + 1}", nxt, M[i]))
            loads.append((nxt, -M[i] * g * N.y))
        parent, joint = Fi, nxt
    kd = [q[i].diff() - u[i] for i in range(n)]
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    return q, u, consts, km


def parse_variant(v):
    plane, angles, kind = v.split("-")
    assert plane in ("planar", "spatial") and angles in ("relative", "absolute")
    assert kind in ("particle", "rigid")
    return plane, angles, kind


def one(variant, n):
    """Run one case, printing `derive SECONDS CPU_SECONDS` and then `cse OPS TRIG SECONDS`."""
    plane, angles, kind = parse_variant(variant)
    t0, c0 = time.perf_counter(), time.process_time()
    q, u, _, km = chain(n, angles, plane, kind)
    Mm, f = km.mass_matrix, km.forcing
    print(f"derive {time.perf_counter() - t0:.3f} {time.process_time() - c0:.3f}", flush=True)
    plain = {s: sm.Symbol(str(s.func)) for s in list(q) + list(u)}
    exprs = [e.xreplace(plain) for e in list(Mm) + list(f)]
    t0 = time.perf_counter()
    reps, reduced = sm.cse(exprs)
    cse_s = time.perf_counter() - t0
    outs = [r for _, r in reps] + list(reduced)
    ops = sum(sm.count_ops(e, visual=False) for e in outs)
    trig = sum(1 for e in outs for x in sm.preorder_traversal(e) if isinstance(x, (sm.sin, sm.cos, sm.tan)))
    print(f"cse {ops} {trig} {cse_s:.3f}", flush=True)


def run_case(variant, n, timeout):
    """([derive_s, cse_ops, trig_calls, cse_s, derive_cpu_s] as strings, whether it timed out);
    "over 5 min" where the timeout hit."""
    over = "over 5 min" if timeout == 300 else f"over {timeout} s"
    with tempfile.TemporaryFile(mode="w+") as out:
        p = subprocess.Popen([sys.executable, os.path.abspath(__file__), "--one", variant, str(n)],
                             stdout=out, stderr=subprocess.STDOUT)
        try:
            p.wait(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
            timed_out = True
        out.seek(0)
        lines = out.read().splitlines()
    derive = next((ln.split()[1:] for ln in lines if ln.startswith("derive ")), None)
    cse = next((ln.split()[1:] for ln in lines if ln.startswith("cse ")), None)
    if not timed_out and (derive is None or cse is None):
        raise RuntimeError(f"{variant} n={n} failed:\n" + "\n".join(lines))
    if derive is None:
        return [over, "", "", "", ""], True
    if cse is None:
        return [derive[0], over, "", "", derive[1]], True
    return [derive[0], cse[0], cse[1], cse[2], derive[1]], False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--variants", default=",".join(DEFAULT_VARIANTS))
    ap.add_argument("--ns", default="5,10,20,40,80,200")
    ap.add_argument("--timeout", type=int, default=300, help="seconds per case")
    ap.add_argument("--out", default=os.path.join(HERE, "sympy_results.csv"))
    ap.add_argument("--one", nargs=2, metavar=("VARIANT", "N"), help="run one case in this process")
    a = ap.parse_args()
    if a.one:
        one(a.one[0], int(a.one[1]))
        return
    variants = a.variants.split(",")
    for v in variants:
        parse_variant(v)
    ns = [int(x) for x in a.ns.split(",")]
    rows = []
    load_before = os.getloadavg()
    for v in variants:
        for n in ns:
            cols, over = run_case(v, n, a.timeout)
            rows.append([v, str(n)] + cols)
            print(",".join(rows[-1]), file=sys.stderr, flush=True)
            if over:
                break
    with open(a.out, "w") as fh:
        fh.write(f"# sympy_chain.py, {datetime.date.today().isoformat()}, SymPy {sm.__version__}, "
                 f"Python {platform.python_version()}, {platform.machine()} {os.cpu_count()} cores; "
                 f"one process per case, timeout {a.timeout} s; larger n of a variant not run after "
                 f"a timeout\n")
        fh.write(f"# load average (1, 5, 15 min) at the start {load_before[0]:.1f} {load_before[1]:.1f} "
                 f"{load_before[2]:.1f}, at the end {' '.join(f'{x:.1f}' for x in os.getloadavg())}\n")
        fh.write("variant,n,derive_s,cse_ops,trig_calls,cse_s,derive_cpu_s\n")
        for r in rows:
            fh.write(",".join(r) + "\n")


if __name__ == "__main__":
    main()
