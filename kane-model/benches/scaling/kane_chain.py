"""Our side of the derivation-scaling benchmark: `kane` on the chains of chain_model.py, timed.

    python3 kane_chain.py [--variants V[=N,N,...] ...] [--ns 5,10,20,40,80,200] [--timeout 120]
                          [--kane PATH] [--target-dir DIR] [--out kane_results.csv]
    python3 kane_chain.py --table [--out kane_results.csv] [--sympy sympy_results.csv]

Variants are named PLANE-ANGLES-KIND as in sympy_chain.py (a `-cart` suffix pivots the chain
on a cart); `V=5,10,20` gives a variant its own n (the others take --ns). Default: the three
planar variants of sympy_results.csv at 5,10,20,40,80,200 and spatial-relative-rigid at
5,10,20. Needs the release CLI
(`cargo build --release -p kane-model --bin kane`) and, for the compile and rhs columns, cargo
working offline. Every case's model file is `chain_model.py --links N ... --inputs` (the INPUT
lines give every parameter a default; they are not folded into the equations). Per case:

* derive_s, derive_mb: `kane check FILE` (parse, derive, check), wall seconds and peak resident
  MB (`/usr/bin/time -f "%e %M"`, or getrusage in a wrapper process where it is missing).
* eoms_s, eoms_bytes: `kane eoms FILE`, wall seconds and the bytes it prints.
* gen_s, gen_mb: `kane gen FILE --stats -o m.rs`, wall seconds and peak MB; module_bytes its size;
  rhs_ops from its line "lowered program: rhs N operations per call".
* rhs_sin, rhs_cos, rhs_sin_cos: the `.sin()`, `.cos()` and `.sin_cos()` calls in the module's
  `rhs_with_constants` function (what one rhs evaluation computes); module_trig: all three in the whole
  module (rhs_lanes, outputs, Taylor coefficients repeat them).
* compile_s, compile_mb: `cargo build --release --offline` of a small crate whose `main.rs` is
  `mod m;` (the module, m.rs) plus a timing loop, kane-model being built already (the target
  directory persists, --target-dir): the time of the crate alone after its m.rs changed. Only
  what main reaches (the `rhs_with_constants` path) goes through code generation; the whole module is
  parsed and type-checked.
* rhs_ns: that binary's `m::rhs_with_constants::<f64>` at a fixed state (q_i = 0.3 sin i,
  u_i = 0.5 cos i), default parameters (1.0 where a default is NaN), in batches of about 20 ms:
  the median over 9 batches, nanoseconds per call.

Each step is killed after --timeout seconds (default 120), written "over 120 s"; the kane steps
also run under an address-space limit (--mem-limit-gb, default 8; a step over it fails and is
written "over 8 GB"). A step that did not finish is not run for the variant's larger n (written
"not run"), nor are the steps that need its output (compile and rhs need gen). The CSV has the
date, the git commit, the machine and the load average in # comments, and is rewritten after
every case.

`--table` joins kane_results.csv and sympy_results.csv into a markdown table and prints, per
variant, the exponent of rhs operations in n fitted by least squares on the logs over
20 <= n <= 200.
"""
import argparse
import datetime
import math
import os
import platform
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DEFAULT_VARIANTS = ["planar-relative-particle", "planar-absolute-particle", "planar-relative-rigid",
                    "spatial-relative-rigid=5,10,20"]
COLUMNS = ["variant", "n", "derive_s", "derive_mb", "eoms_s", "eoms_bytes", "gen_s", "gen_mb",
           "module_bytes", "rhs_ops", "rhs_sin", "rhs_cos", "rhs_sin_cos", "module_trig",
           "compile_s", "compile_mb", "rhs_ns"]
TIME = "/usr/bin/time"

CARGO_TOML = """[package]
name = "kane_scaling_bench"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
kane-model = {{ path = "{path}" }}

[workspace]
"""

MAIN_RS = r"""//! Times the generated module's `rhs_with_constants` at a fixed state (kane_chain.py).
#[allow(dead_code, unused_imports)]
mod m;

use kane_model::runtime::GeneratedModel;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let mut p = <m::Model as GeneratedModel>::Params::default();
    for name in m::INFO.param_names {
        if m::Model::param(&p, name).map_or(true, f64::is_nan) {
            m::Model::set_param(&mut p, name, 1.0);
        }
    }
    let d = m::param_constants(&p);
    let nq = m::INFO.n_coordinates;
    let y: Vec<f64> = (0..m::N_STATES)
        .map(|i| if i < nq { 0.3 * ((i + 1) as f64).sin() } else { 0.5 * ((i - nq + 1) as f64).cos() })
        .collect();
    let mut dy = vec![0.0f64; m::N_STATES];
    let mut batch = |calls: usize| {
        let t0 = Instant::now();
        for _ in 0..calls {
            m::rhs_with_constants(0.0f64, black_box(&y[..]), black_box(&p), black_box(&d), &mut dy);
            black_box(&mut dy);
        }
        t0.elapsed().as_secs_f64()
    };
    let mut calls = 1usize;
    while batch(calls) < 0.02 {
        calls *= 2;
    }
    let mut ns: Vec<f64> = (0..9).map(|_| batch(calls) * 1e9 / calls as f64).collect();
    ns.sort_by(|a, b| a.partial_cmp(b).unwrap());
    m::rhs_with_constants(0.0f64, &y[..], &p, &d, &mut dy);
    let finite = dy.iter().all(|v| v.is_finite());
    println!("ns_per_call {:.1} calls_per_batch {} finite {}", ns[4], calls, finite);
}
"""


def parse_variant(v):
    """PLANE-ANGLES-KIND, or PLANE-ANGLES-KIND-cart for the chain pivoted on a cart."""
    parts = v.split("-")
    assert len(parts) == 3 or (len(parts) == 4 and parts[3] == "cart"), v
    plane, angles, kind = parts[:3]
    assert plane in ("planar", "spatial") and angles in ("relative", "absolute"), v
    assert kind in ("particle", "rigid"), v
    return plane, angles, kind + ("-cart" if len(parts) == 4 else "")


class Step:
    """One command's outcome: wall seconds, peak MB, return code, or why it did not finish."""

    def __init__(self, secs=None, mb=None, rc=None, over=None, err=""):
        self.secs, self.mb, self.rc, self.over, self.err = secs, mb, rc, over, err

    @property
    def ok(self):
        return self.over is None and self.rc == 0


def run(cmd, timeout, stdout_path=None, cwd=None, env=None, mem_gb=None):
    """Runs cmd under /usr/bin/time (or the getrusage wrapper) in its own process group, killed
    after `timeout` seconds; stdout to stdout_path (else discarded), stderr kept in Step.err."""
    with tempfile.TemporaryDirectory() as tmp:
        tfile = os.path.join(tmp, "time")
        if os.path.exists(TIME):
            full = [TIME, "-f", "%e %M", "-o", tfile] + cmd
        else:
            full = [sys.executable, os.path.abspath(__file__), "--rusage", tfile, "--"] + cmd

        def limit():
            if mem_gb:
                b = int(mem_gb * 2**30)
                resource.setrlimit(resource.RLIMIT_AS, (b, b))

        out = open(stdout_path, "wb") if stdout_path else subprocess.DEVNULL
        err = open(os.path.join(tmp, "err"), "w+b")
        t0 = time.perf_counter()
        p = subprocess.Popen(full, stdout=out, stderr=err, cwd=cwd, env=env,
                             start_new_session=True, preexec_fn=limit)
        try:
            p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            return Step(over=f"over {timeout:g} s")
        finally:
            if stdout_path:
                out.close()
        secs = time.perf_counter() - t0
        err.seek(0)
        text = err.read().decode(errors="replace")
        err.close()
        mb = None
        try:
            with open(tfile) as fh:
                last = fh.read().split("\n")
                line = [ln for ln in last if re.match(r"^[0-9.]+ [0-9]+$", ln.strip())][-1]
                mb = int(line.split()[1]) / 1024
        except (OSError, IndexError):
            pass
        st = Step(secs=secs, mb=mb, rc=p.returncode, err=text)
        if p.returncode != 0 and mem_gb and "memory allocation" in text:
            st.over = f"over {mem_gb:g} GB"
        return st


def rusage_wrapper(tfile, cmd):
    """The fallback for /usr/bin/time: run cmd, write "SECONDS PEAK_KB" (ru_maxrss of the only
    child) to tfile, exit with its code."""
    t0 = time.perf_counter()
    rc = subprocess.call(cmd)
    kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    with open(tfile, "w") as fh:
        fh.write(f"{time.perf_counter() - t0:.2f} {kb}\n")
    sys.exit(rc)


def trig_counts(module):
    """(sin, cos, sin_cos) calls in rhs_with_constants, and all of them in the module."""
    pat = {"sin": r"\.sin\(\)", "cos": r"\.cos\(\)", "sin_cos": r"\.sin_cos\(\)"}
    m = re.search(r"^pub fn rhs_with_constants\b.*?^}", module, re.S | re.M)
    body = m.group(0) if m else ""
    rhs = [len(re.findall(p, body)) for p in pat.values()]
    return rhs, sum(len(re.findall(p, module)) for p in pat.values())


def fmt(x, digits=3):
    return "" if x is None else f"{x:.{digits}f}"


class Bench:
    def __init__(self, a):
        self.a = a
        self.kane = a.kane
        self.work = tempfile.mkdtemp(prefix="kane_chain_")
        self.crate = os.path.join(self.work, "crate")
        os.makedirs(os.path.join(self.crate, "src"))
        with open(os.path.join(self.crate, "Cargo.toml"), "w") as fh:
            fh.write(CARGO_TOML.format(path=os.path.join(REPO, "kane-model")))
        shutil.copy(os.path.join(REPO, "Cargo.lock"), os.path.join(self.crate, "Cargo.lock"))
        with open(os.path.join(self.crate, "src", "main.rs"), "w") as fh:
            fh.write(MAIN_RS)
        self.env = dict(os.environ, CARGO_TARGET_DIR=a.target_dir)
        self.compile_ok = not a.no_compile

    def cargo(self, timeout):
        return run(["cargo", "build", "--release", "--offline", "--quiet"], timeout,
                   cwd=self.crate, env=self.env)

    def warm_up(self):
        """Builds the crate once with a small module so kane-model and its dependencies are built."""
        model = os.path.join(self.work, "warm.al")
        with open(model, "w") as fh:
            fh.write(chain_text(3, "planar", "relative", "particle"))
        st = run([self.kane, "gen", model, "-o", os.path.join(self.crate, "src", "m.rs")], 60)
        if not st.ok:
            sys.exit(f"kane gen of the warm-up model failed:\n{st.err}")
        print(f"building kane-model for the timing crate in {self.a.target_dir} ...", file=sys.stderr)
        st = self.cargo(3600)
        if not st.ok:
            sys.exit(f"the timing crate does not build:\n{st.err}")
        print(f"  {st.secs:.1f} s", file=sys.stderr)

    def case(self, variant, n, dead):
        """One row; `dead` maps a step name to why it is not run any more for this variant."""
        plane, angles, kind = parse_variant(variant)
        row = dict.fromkeys(COLUMNS, "")
        row["variant"], row["n"] = variant, str(n)
        base = os.path.join(self.work, f"{variant}-{n}")
        model = base + ".al"
        with open(model, "w") as fh:
            fh.write(chain_text(n, plane, angles, kind))
        T, G = self.a.timeout, self.a.mem_limit_gb

        def record(step, st, scol, mcol=None):
            if not st.ok:
                last = (st.err.strip().splitlines() or [""])[-1]
                why = st.over or f"failed (exit {st.rc}): {last}"
                row[scol] = st.over or f"failed (exit {st.rc})"
                dead[step] = why
                print(f"  {variant} n={n} {step}: {why}", file=sys.stderr)
                return False
            row[scol] = fmt(st.secs)
            if mcol:
                row[mcol] = fmt(st.mb, 1)
            return True

        def skipped(step, needs=()):
            for s in (step,) + tuple(needs):
                if s in dead:
                    return True
            return False

        if skipped("derive"):
            return None
        st = run([self.kane, "check", model], T, mem_gb=G)
        if not record("derive", st, "derive_s", "derive_mb"):
            return row
        if skipped("eoms"):
            row["eoms_s"] = "not run"
        else:
            out = base + ".eoms"
            st = run([self.kane, "eoms", model], T, stdout_path=out, mem_gb=G)
            if record("eoms", st, "eoms_s"):
                row["eoms_bytes"] = str(os.path.getsize(out))
            os.remove(out)
        if skipped("gen"):
            row["gen_s"] = "not run"
            return row
        mod = os.path.join(self.work, "m.rs")
        st = run([self.kane, "gen", model, "--stats", "-o", mod], T, mem_gb=G)
        if not record("gen", st, "gen_s", "gen_mb"):
            return row
        m = re.search(r"lowered program: rhs (\d+) operations per call", st.err)
        row["rhs_ops"] = m.group(1) if m else ""
        with open(mod) as fh:
            text = fh.read()
        row["module_bytes"] = str(len(text.encode()))
        (s, c, sc), allt = trig_counts(text)
        row["rhs_sin"], row["rhs_cos"], row["rhs_sin_cos"], row["module_trig"] = map(str, (s, c, sc, allt))
        if not self.compile_ok:
            return row
        if skipped("compile"):
            row["compile_s"] = "not run"
            return row
        shutil.move(mod, os.path.join(self.crate, "src", "m.rs"))
        st = self.cargo(T)
        if not record("compile", st, "compile_s", "compile_mb"):
            return row
        exe = os.path.join(self.a.target_dir, "release", "kane_scaling_bench")
        out = base + ".run"
        st = run([exe], T, stdout_path=out)
        with open(out) as fh:
            line = fh.read()
        os.remove(out)
        if record("rhs", st, "rhs_ns"):
            m = re.search(r"ns_per_call ([0-9.]+) .* finite (\w+)", line)
            row["rhs_ns"] = m.group(1) if m else "?"
            if m and m.group(2) != "true":
                print(f"  {variant} n={n}: rhs gives non-finite values", file=sys.stderr)
        return row


def chain_text(n, plane, angles, kind):
    sys.path.insert(0, HERE)
    from chain_model import chain_model
    links, _, cart = kind.partition("-")
    return chain_model(n, angles, plane, links, inputs=True, cart=cart == "cart")


def git_commit():
    try:
        c = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], cwd=REPO, capture_output=True,
                           text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=REPO,
                               capture_output=True, text=True).stdout.strip()
        return c + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_csv(path, header, rows):
    with open(path, "w") as fh:
        for h in header:
            fh.write(f"# {h}\n")
        fh.write(",".join(COLUMNS) + "\n")
        for r in rows:
            fh.write(",".join(r[c] for c in COLUMNS) + "\n")


def measure(a):
    if not os.path.exists(a.kane):
        sys.exit(f"{a.kane} missing: cargo build --release -p kane-model --bin kane")
    cases = []
    for v in a.variants:
        name, _, ns = v.partition("=")
        parse_variant(name)
        cases.append((name, [int(x) for x in (ns or a.ns).split(",")]))
    bench = Bench(a)
    if bench.compile_ok:
        bench.warm_up()
    load0 = os.getloadavg()
    rustc = subprocess.run(["rustc", "--version"], capture_output=True, text=True).stdout.strip()
    header = [f"kane_chain.py, {datetime.date.today().isoformat()}, git {git_commit()}, {rustc}, "
              f"{platform.machine()} {os.cpu_count()} cores; timeout {a.timeout:g} s per step, "
              f"kane steps limited to {a.mem_limit_gb:g} GB; a step not finished is not run for "
              f"the variant's larger n",
              "sin/cos counted in the module's rhs_with_constants (rhs_sin, rhs_cos, rhs_sin_cos) and in "
              "the whole module (module_trig); compile: release build of the module's crate alone",
              f"load average (1, 5, 15 min) at the start {load0[0]:.1f} {load0[1]:.1f} {load0[2]:.1f}"]
    rows = []
    for variant, ns in cases:
        dead = {}
        for n in ns:
            row = bench.case(variant, n, dead)
            if row is None:
                print(f"  {variant} n={n}: not run (derive over the limit at a smaller n)",
                      file=sys.stderr)
                continue
            rows.append(row)
            print(",".join(row[c] for c in COLUMNS), file=sys.stderr, flush=True)
            la = os.getloadavg()
            write_csv(a.out, header + [f"load average (1, 5, 15 min) at the end "
                                       f"{la[0]:.1f} {la[1]:.1f} {la[2]:.1f}"], rows)
    shutil.rmtree(bench.work, ignore_errors=True)
    table(a.out, a.sympy)


def read_csv(path):
    rows = []
    with open(path) as fh:
        lines = [ln.rstrip("\n") for ln in fh if not ln.startswith("#") and ln.strip()]
    cols = lines[0].split(",")
    for ln in lines[1:]:
        rows.append(dict(zip(cols, ln.split(","))))
    return rows


def num(s):
    try:
        return float(s)
    except (TypeError, ValueError):
        return None


def table(ours_path, sympy_path):
    """Prints the joined markdown table and the fitted exponents of rhs operations."""
    ours = read_csv(ours_path)
    sym = {(r["variant"], r["n"]): r for r in read_csv(sympy_path)} if os.path.exists(sympy_path) else {}
    keys = []
    for r in ours:
        keys.append((r["variant"], r["n"]))
    for k in sym:
        if k not in keys:
            keys.append(k)
    order = {v: i for i, v in enumerate(dict.fromkeys(k[0] for k in keys))}
    keys.sort(key=lambda k: (order[k[0]], int(k[1])))
    byk = {(r["variant"], r["n"]): r for r in ours}

    def t(s, d=2):
        x = num(s)
        if x is None:
            return s or ""
        return f"{x:,.{d}f}" if x < 1000 else f"{x:,.0f}"

    def i(s):
        x = num(s)
        return f"{int(x):,}" if x is not None else (s or "")

    print("| variant | n | derive s | eoms s / bytes | gen s / MB peak | module KB | rhs ops | "
          "sin/cos | rhs ns | compile s | SymPy derive s | SymPy CSE ops |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for k in keys:
        r, s = byk.get(k, {}), sym.get(k, {})
        eoms = t(r.get("eoms_s", ""))
        if r.get("eoms_bytes"):
            eoms += f" / {i(r['eoms_bytes'])}"
        gen = t(r.get("gen_s", ""))
        if num(r.get("gen_mb")) is not None:
            gen += f" / {num(r['gen_mb']):,.0f}"
        kb = f"{num(r['module_bytes']) / 1024:,.0f}" if num(r.get("module_bytes")) else ""
        trig = ", ".join(f"{r[c]} {c[4:]}" for c in ("rhs_sin", "rhs_cos", "rhs_sin_cos")
                         if num(r.get(c)))
        if not trig and r.get("rhs_sin") == "0" and r.get("rhs_sin_cos") == "0":
            trig = "0"
        ns = r.get("rhs_ns", "")
        ns = f"{num(ns):,.0f}" if num(ns) is not None else ns
        print(f"| {k[0]} | {k[1]} | {t(r.get('derive_s', ''))} | {eoms} | {gen} | {kb} | "
              f"{i(r.get('rhs_ops', ''))} | {trig} | {ns} | {t(r.get('compile_s', ''), 1)} | "
              f"{t(s.get('derive_s', ''))} | {i(s.get('cse_ops', ''))} |")
    print()
    print("Exponent of rhs operations in n (least squares on log ops vs log n, 20 <= n <= 200):")
    print()
    for v in order:
        pts = [(int(r["n"]), num(r["rhs_ops"])) for r in ours
               if r["variant"] == v and 20 <= int(r["n"]) <= 200 and num(r.get("rhs_ops"))]
        if len(pts) < 2:
            print(f"- {v}: fewer than two n in 20..200 with rhs operations ({', '.join(str(p[0]) for p in pts) or 'none'})")
            continue
        xs = [math.log(p[0]) for p in pts]
        ys = [math.log(p[1]) for p in pts]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print(f"- {v}: {slope:.2f} (n = {', '.join(str(p[0]) for p in pts)})")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--rusage":
        rusage_wrapper(sys.argv[2], sys.argv[4:])
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--variants", nargs="+", default=DEFAULT_VARIANTS,
                    help="VARIANT or VARIANT=N,N,... (PLANE-ANGLES-KIND)")
    ap.add_argument("--ns", default="5,10,20,40,80,200", help="n for variants without their own")
    ap.add_argument("--timeout", type=float, default=120, help="seconds per step")
    ap.add_argument("--mem-limit-gb", type=float, default=8, help="address-space limit of kane steps")
    ap.add_argument("--kane", default=os.path.join(REPO, "target", "release", "kane"))
    ap.add_argument("--target-dir", default=os.path.join(tempfile.gettempdir(), "kane_chain_target"),
                    help="cargo target directory of the timing crate (kept between runs)")
    ap.add_argument("--no-compile", action="store_true", help="leave out compile_s and rhs_ns")
    ap.add_argument("--out", default=os.path.join(HERE, "kane_results.csv"))
    ap.add_argument("--sympy", default=os.path.join(HERE, "sympy_results.csv"))
    ap.add_argument("--table", action="store_true", help="only print the table of --out and --sympy")
    a = ap.parse_args()
    if a.table:
        table(a.out, a.sympy)
    else:
        measure(a)


if __name__ == "__main__":
    main()
