"""Ensemble throughput at equal error, side by side in one run: a Monte Carlo sweep of the paper's
gimbal (Trial 3, t = 0..5 s; Y and Z in 0..20 N m, U3 in 50..150 rad/s; Latin hypercube) run by
`gyro-sim sweep` and by heyoka (the same members, read from gyro-sim's sweep.csv), three ways:
- "heyoka ensemble": ensemble_propagate_grid (threads), which copies the integrator for every
  member and propagates the copy;
- "heyoka loop": one integrator (taylor_adaptive) reused for every member in a Python loop (set
  time, state and parameters, then propagate_grid), one thread;
- "heyoka batch N": its SIMD batch mode (taylor_adaptive_batch, N members per instruction; N from
  --lanes, 4 and 8 by default; hy.recommended_simd_size() is printed), one thread, reused the
  same way, batch after batch.
All of them and gyro-sim integrate the same equations (models.gimbal, the hand derivation, which
equals the generated model gimbal_gyroscope) and give the same output, each member's final state.

Not needed by the build or the tests. Needs heyoka and numpy (pip install heyoka) and
target/release/gyro-sim (cargo build --release -p gyro-sim). Run from the repository root:

    python3 gyro-sim/benches/peers/gimbal_ensemble.py [--members 10000] [--rounds 3] [--lanes 4,8]

(the binary is read from $CARGO_TARGET_DIR/release, else target/release).

Error, measured the same way for every tool: the largest over the first 200 members and the six
states of |final - reference| / max(1, |reference|), the reference being heyoka at tol 1e-16 on
the same equations (the hand derivation of tests/tests/gimbal_hand_derivation.rs, which equals
the generated model). Time: the wall time of the whole ensemble. gyro-sim: the whole `gyro-sim sweep` command, a cold
process (start, scene parsing, its members' setup and sweep.csv written; the model is compiled
into the binary, nothing is compiled at run time). heyoka: warm, propagation only (the
integrators are built and LLVM-compiled beforehand, outside the time; the loop's and the batch's
Python loop over members is inside it).
Throughput per core: members / time / cores used. Each tool's time at gyro-sim's errors is
interpolated in log-log between its tolerances; tools alternate round by round; medians.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time
from math import pi
from pathlib import Path

import heyoka as hy
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import models  # noqa: E402
from equal_error import at_error  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
GYRO_SIM = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "release" / "gyro-sim"
T_FINAL = 5.0
SCENE = """title = "gimbal ensemble (Trial 3 equations)"
model = "gimbal_gyroscope"
t_final = 5.0
output_step = 5.0
outputs = ["Q1", "Q2", "Q3", "U1", "U2", "U3"]
[integrator]
method = "{method}"
rtol = {tol}
atol = {tol}
[parameters]
Y = 10.0
Z = 10.0
[initial]
U3 = "100 rad/s"
"""


def run_sweep(members, tol, method, out, threads):
    scene = out / f"scene-{method}-{tol}.toml"
    scene.write_text(SCENE.format(method=method, tol=tol))
    folder = out / f"sweep-{method}-{tol}-{threads}"
    subprocess.run(["rm", "-rf", str(folder)], check=True)
    args = [str(GYRO_SIM), "sweep", str(scene), "--vary", "Y=0:20", "--vary", "Z=0:20", "--vary", "U3=50:150 rad/s",
            "--samples", str(members), "--seed", "1", "--out", str(folder)]
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    start = time.perf_counter()
    subprocess.run(args, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    rows = list(csv.DictReader(open(folder / "sweep.csv")))
    assert all(r["status"] == "ok" for r in rows), "a member failed"
    final = np.array([[float(r[f"final_q{i}_deg"]) * pi / 180 for i in (1, 2, 3)]
                      + [float(r[f"final_u{i}_rad_per_s"]) for i in (1, 2, 3)] for r in rows])
    varied = np.array([[float(r["Y"]), float(r["Z"]), float(r["U3"])] for r in rows])
    return wall, varied, final


def heyoka_ensemble(ta, varied, workers):
    def gen(t, i):
        t.time = 0.0
        t.state[:] = [0, 0, 0, 0, 0, varied[i, 2]]
        t.pars[:] = varied[i, :2]
        return t

    start = time.perf_counter()
    res = hy.ensemble_propagate_grid(ta, [0.0, T_FINAL], len(varied), gen, max_workers=workers)
    wall = time.perf_counter() - start
    return wall, np.array([r[-1][-1] for r in res])


def heyoka_loop(ta, varied):
    """One integrator reused for every member: set time, state and parameters, propagate_grid."""
    n = len(varied)
    out = np.empty((n, 6))
    grid = np.array([0.0, T_FINAL])
    start = time.perf_counter()
    for i in range(n):
        ta.time = 0.0
        ta.state[:] = 0.0
        ta.state[5] = varied[i, 2]
        ta.pars[:] = varied[i, :2]
        out[i] = ta.propagate_grid(grid)[-1][-1]
    return time.perf_counter() - start, out


def heyoka_batch(tab, varied):
    n, b = len(varied), tab.batch_size
    out = np.empty((n, 6))
    start = time.perf_counter()
    for k in range(0, n, b):
        chunk = varied[k:k + b]
        m = len(chunk)
        pad = np.vstack([chunk, np.repeat(chunk[-1:], b - m, axis=0)])
        tab.set_time(0.0)
        tab.state[:] = 0.0
        tab.state[5, :] = pad[:, 2]
        tab.pars[:] = pad[:, :2].T
        res = tab.propagate_grid(np.repeat([[0.0], [T_FINAL]], b, axis=1))
        out[k:k + m] = res[1][-1].T[:m]
    return time.perf_counter() - start, out


def error(final, ref):
    k = len(ref)
    return float(np.max(np.abs(final[:k] - ref) / np.maximum(1.0, np.abs(ref))))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--members", type=int, default=10000)
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--method", default="dop853")
    p.add_argument("--lanes", default="4,8", help="batch sizes of taylor_adaptive_batch")
    args = p.parse_args()
    lanes = [int(x) for x in args.lanes.split(",") if x]
    cores = os.cpu_count()
    work = Path(tempfile.mkdtemp(prefix="gimbal-ensemble-"))
    ours_tols = [1e-7, 1e-9, 1e-11]
    hy_tols = [1e-6, 1e-8, 1e-10, 1e-12, 1e-14]
    _, varied, _ = run_sweep(args.members, 1e-9, args.method, work, cores)
    sysm = models.gimbal()
    ref_ta = hy.taylor_adaptive(sysm, [0.0] * 6, tol=1e-16, pars=[0.0, 0.0])
    ref = heyoka_ensemble(ref_ta, varied[:200], 1)[1]
    tas = {t: hy.taylor_adaptive(sysm, [0.0] * 6, tol=t, pars=[0.0, 0.0]) for t in hy_tols}
    tabs = {(b, t): hy.taylor_adaptive_batch(sysm, np.zeros((6, b)), tol=t, pars=np.zeros((2, b)))
            for b in lanes for t in hy_tols}
    times = {}
    errors = {}
    for _ in range(args.rounds):
        for tol in ours_tols:
            for threads in (1, cores):
                wall, _, final = run_sweep(args.members, tol, args.method, work, threads)
                times.setdefault(("gyro-sim", threads, tol), []).append(wall)
                errors[("gyro-sim", tol)] = error(final, ref)
        for tol in hy_tols:
            for workers in (1, cores):
                wall, final = heyoka_ensemble(tas[tol], varied, workers)
                times.setdefault(("heyoka ensemble", workers, tol), []).append(wall)
                errors[("heyoka ensemble", tol)] = error(final, ref)
            wall, final = heyoka_loop(tas[tol], varied)
            times.setdefault(("heyoka loop", 1, tol), []).append(wall)
            errors[("heyoka loop", tol)] = error(final, ref)
            for b in lanes:
                wall, final = heyoka_batch(tabs[(b, tol)], varied)
                times.setdefault((f"heyoka batch {b}", 1, tol), []).append(wall)
                errors[(f"heyoka batch {b}", tol)] = error(final, ref)
    med = {k: float(np.median(v)) for k, v in times.items()}
    print(f"{args.members} members, {cores} cores, {args.rounds} rounds (medians); error over 200 members vs heyoka tol 1e-16;"
          f" heyoka {hy.__version__}, recommended_simd_size {hy.recommended_simd_size()}")
    print("| gyro-sim tol | error | tool | threads | time (s) | members/s/core | ratio to gyro-sim |")
    print("|---|---|---|---|---|---|---|")
    for tol in ours_tols:
        err = errors[("gyro-sim", tol)]
        for threads in (1, cores):
            ours = med[("gyro-sim", threads, tol)]
            rows = [("gyro-sim", ours)]
            names = ["heyoka ensemble"]
            if threads == 1:
                names += ["heyoka loop"] + [f"heyoka batch {b}" for b in lanes]
            for name in names:
                rows.append((name, at_error([(errors[(name, t)], med[(name, threads, t)]) for t in hy_tols], err)))
            for tool, secs in rows:
                rate = args.members / secs / threads
                print(f"| {tol:.0e} | {err:.1e} | {tool} | {threads} | {secs:.3f} | {rate:,.0f} | {secs / ours:.2f} |")
    for name in sorted({k[0] for k in errors if k[0] != "gyro-sim"}):
        print(f"{name} errors by tol:", {t: f"{errors[(name, t)]:.1e}" for t in hy_tols})
    print("raw medians (s):", {f"{k[0]}/{k[1]}/{k[2]:.0e}": round(v, 4) for k, v in sorted(med.items())})


if __name__ == "__main__":
    main()
