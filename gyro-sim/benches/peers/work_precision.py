"""Work against precision, side by side in one run: gyro-sim's methods, heyoka (Taylor method,
LLVM-compiled) and SciPy's DOP853 on the same scenes, the error of every tool measured the same
way against the same reference, the tools alternating tolerance by tolerance.

Cases and references (all in the repository):
- trial3: the paper's Trial 3 (gyro-sim/scenes/paper/trial3.toml) against the quadruple-precision
  reference gyro-sim/tests/data/gimbal_trial3_quad.csv (make_quad_references.py); error = largest
  |x - ref| / max(1, |ref|) over the 0.05 s grid and the six states (gyro-sim bench's measure);
- cusp, loops, nospin: the EJS top's presets against the closed forms (gyro-sim/tests/data/ejs/
  top_*.csv, 1 s grid to t = 50); fast: spin 1000 rad/s to t = 10 against
  gyro-sim/tests/data/ejs/top_fast_quad.csv (0.01 s grid); error = largest |axle - axle_ref|;
  fast_spin_aware: the same, gyro-sim on its spin-aware model (ejs/fast_spin_aware.toml,
  model heavy_top_axle) and heyoka on its own copy of the same spin-aware equations
  (models.top_axle; column "heyoka"), plus heyoka on the plain quaternion model of `fast`
  (models.top; column "heyoka quaternion model"), which is not the same equations. Before timing,
  the spin-aware copy is checked against gyro-sim on a short run (check_spin_aware: to 1e-10).

In every other case heyoka integrates the same equations as gyro-sim (its own copy, written from
the hand derivations in models.py), and every tool outputs the states on the same grid.

Time, warm for every tool: gyro-sim's own wall time of the integration (the median of
`run --repeat R` within one process; outputs only the states, no figures, no view); heyoka's
propagate_grid on one integrator built beforehand (LLVM compilation excluded) and SciPy's
solve_ivp (DOP853, right-hand side a heyoka cfunc called from Python), medians of R runs. Each tool's time at errors 1e-6, 1e-9 and
1e-12 is interpolated in log-log between the two tolerances where its error first falls below
the level (blank where it never does).

Not needed by the build or the tests. Needs heyoka, numpy, and scipy unless --no-scipy
(pip install heyoka scipy);
matplotlib for the figures (optional). Run from the repository root, after
`cargo build --release -p gyro-sim` (the binary is read from $CARGO_TARGET_DIR/release, else
target/release):

    python3 gyro-sim/benches/peers/work_precision.py [--cases trial3,cusp,loops,nospin,fast,...]
        [--methods dop853,vern9] [--repeats 7] [--out out/peers]
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import heyoka as hy
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import models  # noqa: E402
from equal_error import at_error  # noqa: E402

ROOT = Path(__file__).resolve().parents[3]
GYRO_SIM = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "release" / "gyro-sim"
DATA = ROOT / "gyro-sim" / "tests" / "data"
LEVELS = [1e-6, 1e-9, 1e-12]
CASES = {
    "trial3": ("paper/trial3.toml", DATA / "gimbal_trial3_quad.csv", 5.0, 0.05),
    "cusp": ("ejs/cusp.toml", DATA / "ejs/top_cusp.csv", 50.0, 1.0),
    "loops": ("ejs/loops.toml", DATA / "ejs/top_loops.csv", 50.0, 1.0),
    "nospin": ("ejs/nospin.toml", DATA / "ejs/top_nospin.csv", 50.0, 1.0),
    "fast": ("ejs/fast.toml", DATA / "ejs/top_fast_quad.csv", 10.0, 0.01),
    # gyro-sim's spin-aware model of the same top (heavy_top_axle); heyoka runs its own copy of
    # the spin-aware equations (models.top_axle) and, as a second column, the quaternion model.
    "fast_spin_aware": ("ejs/fast_spin_aware.toml", DATA / "ejs/top_fast_quad.csv", 10.0, 0.01),
}


def toml_value(v):
    if isinstance(v, str):
        return '"' + v.replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return repr(v)


def bench_scene(case, method, tol, work, t_final=None, step=None):
    """The case's scene with only the states written (no view), at `method` and `tol`."""
    src, _, case_t_final, case_step = CASES[case]
    t_final = t_final or case_t_final
    step = step or case_step
    scene = tomllib.loads((ROOT / "gyro-sim" / "scenes" / src).read_text())
    states = ["Q1", "Q2", "Q3", "U1", "U2", "U3"] if case == "trial3" else ["E4", "E1", "E2", "E3", "W1", "W2", "W3"]
    lines = [f'title = "{case}"', f'model = "{scene["model"]}"', f"t_final = {t_final}", f"output_step = {step}",
             f"outputs = {toml_value(states)}", "[integrator]", f'method = "{method}"',
             f"rtol = {tol}", f"atol = {tol}"]
    for table in ("parameters", "initial", "axle"):
        if table in scene:
            lines.append(f"[{table}]")
            lines += [f"{k} = {toml_value(v)}" for k, v in scene[table].items()]
    path = work / f"{case}-{method}-{tol:.0e}.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def gyro_sim(case, method, tol, repeats, work):
    scene = bench_scene(case, method, tol, work)
    out = work / f"out-{case}-{method}-{tol:.0e}"
    done = subprocess.run([str(GYRO_SIM), "run", str(scene), "--out", str(out), "--repeat", str(repeats)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None
    ms = float(re.search(r"median ([0-9.]+) ms", done.stdout + done.stderr).group(1))
    table = np.loadtxt(out / "trajectory.csv", delimiter=",", skiprows=1)
    if case == "trial3":
        table[:, 1:4] *= np.pi / 180
    return ms, table[:, 1:]


def initial(case):
    if case == "trial3":
        return [0, 0, 0, 0, 0, 100.0], [10.0, 10.0]
    spin, prec = {"cusp": (10, 0), "loops": (10, -1), "nospin": (0, 0), "fast": (1000, 0),
                  "fast_spin_aware": (1000, 0)}[case]
    th = np.pi / 3 if case != "nospin" else np.pi / 180
    return [np.cos(th / 2), np.sin(th / 2), 0, 0, 0, prec * np.sin(th), float(spin)], []


def system(case):
    """heyoka's equations of the case: the same equations as gyro-sim's model."""
    if case == "trial3":
        return models.gimbal()
    return models.top_axle() if case == "fast_spin_aware" else models.top()


def check_spin_aware(work):
    """heyoka's copy of the spin-aware top (models.top_axle) against gyro-sim's heavy_top_axle on a
    short run (t = 0..0.2, every 0.01; both at tight tolerances): the largest difference over the
    quaternion and w / max(1, |w|) must be below 1e-10."""
    scene = bench_scene("fast_spin_aware", "vern9", 1e-14, work, t_final=0.2, step=0.01)
    out = work / "check-spin-aware"
    subprocess.run([str(GYRO_SIM), "run", str(scene), "--out", str(out)], check=True, capture_output=True)
    ours = np.loadtxt(out / "trajectory.csv", delimiter=",", skiprows=1)
    y0, _ = initial("fast_spin_aware")
    ta = hy.taylor_adaptive(models.top_axle(), [float(v) for v in y0], tol=1e-16)
    theirs = ta.propagate_grid(ours[:, 0])[-1]
    diff = np.abs(ours[:, 1:] - theirs) / np.maximum(1.0, np.abs(theirs))
    worst = float(np.max(diff))
    moved = float(np.max(np.abs(theirs[:, 4:6])))
    print(f"check: heyoka's spin-aware top against gyro-sim's heavy_top_axle, t = 0..0.2: largest "
          f"difference {worst:.1e} (w1, w2 reach {moved:.2e})", file=sys.stderr)
    assert worst < 1e-10, f"models.top_axle differs from heavy_top_axle by {worst:.1e}"


def timed(run, repeats):
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append((time.perf_counter() - start) * 1e3)
    return float(np.median(times)), result


def heyoka_run(ta, case, grid, repeats):
    y0, pars = initial(case)

    def run():
        ta.time = 0.0
        ta.state[:] = y0
        if pars:
            ta.pars[:] = pars
        return ta.propagate_grid(grid)[-1].copy()

    return timed(run, repeats)


def scipy_run(case, grid, tol, repeats):
    from scipy.integrate import solve_ivp

    y0, pars = initial(case)
    f = hy.cfunc([r for _, r in system(case)], [v for v, _ in system(case)])

    def rhs(t, y):
        return f(y, pars=pars) if pars else f(y)

    def run():
        sol = solve_ivp(rhs, (0, grid[-1]), y0, method="DOP853", t_eval=grid, rtol=tol, atol=tol)
        return sol.y.T

    return timed(run, repeats)


def error(case, got, ref):
    if case == "trial3":
        return float(np.max(np.abs(got[:, :6] - ref[:, 1:7]) / np.maximum(1.0, np.abs(ref[:, 1:7]))))
    return float(np.max(np.abs(models.axle(got[:, :4]) - models.axle(ref[:, 1:5]))))


def measure(case, methods, repeats, work, use_scipy):
    ref = np.loadtxt(CASES[case][1], delimiter=",", skiprows=1, dtype=str).astype(float)
    grid = ref[:, 0]
    points = {}
    tas = {}
    quat = {}
    for tol in [10.0 ** -k for k in range(4, 16)]:
        for m in methods:
            if tol < 1e-14:
                continue
            r = gyro_sim(case, m, tol, repeats, work)
            if r:
                points.setdefault(f"gyro-sim {m}", []).append((error(case, r[1], ref), r[0], tol))
        if tol not in tas:
            tas[tol] = hy.taylor_adaptive(system(case), [float(v) for v in initial(case)[0]], tol=tol, pars=initial(case)[1])
        ms, got = heyoka_run(tas[tol], case, grid, repeats)
        points.setdefault("heyoka", []).append((error(case, got, ref), ms, tol))
        if case == "fast_spin_aware":
            # Not the same equations: heyoka on the quaternion model of `fast` (the spin sets its steps).
            if tol not in quat:
                quat[tol] = hy.taylor_adaptive(models.top(), [float(v) for v in initial(case)[0]], tol=tol)
            ms, got = heyoka_run(quat[tol], case, grid, repeats)
            points.setdefault("heyoka quaternion model", []).append((error(case, got, ref), ms, tol))
        if use_scipy and tol >= 1e-12:
            ms, got = scipy_run(case, grid, tol, max(1, repeats // 3))
            points.setdefault("scipy dop853", []).append((error(case, got, ref), ms, tol))
    return points


def report(all_points, out):
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "peers_work_precision.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "tool", "tol", "error", "median_ms"])
        for case, points in all_points.items():
            for tool, pts in points.items():
                for e, ms, tol in pts:
                    w.writerow([case, tool, f"{tol:.0e}", f"{e:.3e}", f"{ms:.4f}"])
    tools = sorted({t for p in all_points.values() for t in p})
    quat = "heyoka quaternion model"
    extra = " | best gyro-sim / heyoka quaternion model" if quat in tools else ""
    print("| case | error | " + " | ".join(tools) + " | best gyro-sim / heyoka (same equations)" + extra + " |")
    print("|" + "---|" * (len(tools) + 3 + bool(extra)))
    for case, points in all_points.items():
        for level in LEVELS:
            times = {t: at_error([(e, ms) for e, ms, _ in points.get(t, [])], level) for t in tools}
            ours = [v for t, v in times.items() if t.startswith("gyro-sim") and v == v]
            ratio = min(ours) / times["heyoka"] if ours and times["heyoka"] == times["heyoka"] else float("nan")
            cells = " | ".join("" if v != v else f"{v:.3g} ms" for v in (times[t] for t in tools))
            last = ""
            if extra:
                q = times.get(quat, float("nan"))
                last = f" {min(ours) / q:.2f} |" if ours and q == q else " |"
            print(f"| {case} | {level:.0e} | {cells} | {ratio:.2f} |{last}")
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib not installed: no figure)")
        return
    for case, points in all_points.items():
        plt.figure(figsize=(7, 5))
        for tool, pts in points.items():
            pts = sorted(pts)
            plt.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=tool)
        plt.xlabel("error (same measure for every tool)")
        plt.ylabel("median time (ms)")
        plt.title(case)
        plt.legend()
        plt.grid(True, which="both", alpha=0.3)
        plt.savefig(out / f"peers_{case}.png", dpi=100)
        plt.close()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--cases", default="trial3,cusp,loops,nospin,fast,fast_spin_aware")
    p.add_argument("--methods", default="dop853,vern9")
    p.add_argument("--repeats", type=int, default=7)
    p.add_argument("--no-scipy", action="store_true")
    p.add_argument("--out", default="out/peers")
    args = p.parse_args()
    work = Path(tempfile.mkdtemp(prefix="peers-"))
    if "fast_spin_aware" in args.cases.split(","):
        check_spin_aware(work)
    results = {}
    for case in args.cases.split(","):
        results[case] = measure(case, args.methods.split(","), args.repeats, work, not args.no_scipy)
        print(f"{case}: measured", file=sys.stderr)
    report(results, Path(args.out))


if __name__ == "__main__":
    main()
