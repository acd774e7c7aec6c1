//! A standalone Python program: in comes a [`Plan`]; out goes one `.py` file with the model's
//! `constants`, `rhs` and `row` functions and a `main` that integrates with SciPy's
//! `solve_ivp` (DOP853) and writes the CSV. It needs NumPy and SciPy.

use crate::expr::Func;
use crate::program::ir::Input;

use super::dialect::{self, Dialect};
use super::plan::Plan;
use super::{comment_lines, Program};

/// Python's spelling (scalars through `math`).
pub(super) struct Python {
    /// Coordinates before speeds in the state.
    pub(super) n_coordinates: usize,
}

impl Dialect for Python {
    fn input(&self, input: Input) -> String {
        dialect::array_read(input, self.n_coordinates, 0, ("[", "]"), "nan")
    }
    fn number(&self, x: f64) -> String {
        dialect::shortest(x)
    }
    fn powi(&self, a: &str, k: i32) -> String {
        match k {
            2 => format!("{a} * {a}"),
            _ => format!("{a} ** {k}"),
        }
    }
    fn powf(&self, a: &str, b: &str) -> String {
        format!("{a} ** {b}")
    }
    fn func(&self, f: Func, a: &str) -> String {
        match f {
            Func::Abs => format!("abs({a})"),
            Func::Sign => format!("float(({a} > 0) - ({a} < 0))"),
            other => format!("{}({a})", dialect::common_name(other)),
        }
    }
    fn atan2(&self, a: &str, b: &str) -> String {
        format!("atan2({a}, {b})")
    }
    fn assign(&self, name: &str, value: &str) -> String {
        format!("{name} = {value}")
    }
    fn nan(&self) -> String {
        "nan".into()
    }
}

/// The modules every program imports (then SciPy's part it uses).
pub(super) const IMPORTS: &str = "import math\nimport os\nimport sys\nfrom math import (acos, asin, atan, atan2, cos, cosh, exp, log, nan, sin, sinh, sqrt,\n                  tan, tanh)\n\nimport numpy as np\n";

/// The Python program of `plan`, its file named `stem`.
pub(super) fn program(plan: &Plan<'_>, stem: &str, about: &Program) -> String {
    let py = Python { n_coordinates: plan.info.n_coordinates };
    let mut out = comment_lines(
        &about.header_lines(&format!("python3 {stem}.py [OUT.csv]"), plan.once),
        "# ",
        "# ",
        "",
    );
    out.push_str(IMPORTS);
    out.push_str("from scipy.integrate import solve_ivp\n\n");
    out.push_str(&values(plan, stem));
    out.push_str(&functions(plan, &py));
    out.push_str(&MAIN.replace("STEM", stem));
    out.push_str(CLOSE_OUTPUT);
    out
}

/// A Python list of `values` (nan where not finite).
pub(super) fn list(values: &[f64]) -> String {
    let items: Vec<String> =
        values.iter().map(|v| if v.is_finite() { dialect::shortest(*v) } else { "nan".into() }).collect();
    format!("[{}]", items.join(", "))
}

/// A Python list of strings.
pub(super) fn names(values: &[&str]) -> String {
    let items: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
    format!("[{}]", items.join(", "))
}

/// The INPUT values and run settings.
fn values(plan: &Plan<'_>, stem: &str) -> String {
    let info = plan.info;
    let s = plan.settings;
    let open: Vec<&str> = info.open_inputs.iter().map(|i| info.param_names[*i]).collect();
    let mut out = format!("NAME = {stem:?}\n");
    out.push_str("# The file's INPUT values (internal units: angles in radians); nan where it gives none.\n");
    out.push_str(&format!("P0 = {}\nP_NAMES = {}\n", list(&plan.start_params()), names(info.param_names)));
    out.push_str(&format!("Y0 = {}\nY_NAMES = {}\n", list(&plan.initial), names(info.state_names)));
    out.push_str(&format!("OPEN_INPUTS = {}\nHEADER = {:?}\n", names(&open), plan.header()));
    out.push_str(&format!(
        "T_FINAL, STEP, RTOL, ATOL = {}, {}, {}, {}\n\n\n",
        dialect::shortest(s.t_final),
        dialect::shortest(s.output_step),
        dialect::shortest(s.rtol),
        dialect::shortest(s.atol)
    ));
    out
}

/// The statements, indented as a function body.
pub(super) fn body(out: &mut String, lines: &[String]) {
    lines.iter().for_each(|l| out.push_str(&format!("    {l}\n")));
}

/// `constants`, `rhs` and `row`.
fn functions(plan: &Plan<'_>, py: &Python) -> String {
    let p = plan.program;
    let mut out = String::new();
    let (lines, results) = dialect::print(&p.param_constants, py, "c");
    out.push_str(
        "def constants(p):\n    \"\"\"The parameter-only quantities of p (once per parameter set).\"\"\"\n",
    );
    body(&mut out, &lines);
    out.push_str(&format!("    return [{}]\n\n\n", results.join(", ")));
    let (lines, results) = dialect::print(&p.rhs, py, "v");
    out.push_str("def rhs(t, y, p, k):\n    \"\"\"dy = f(t, y): coordinates' rates, then speeds' rates; k = constants(p).\"\"\"\n");
    body(&mut out, &lines);
    out.push_str(&format!("    return [{}]\n\n\n", results.join(", ")));
    out.push_str("def row(t, y, p, k):\n    \"\"\"One written row after t: each column in its unit.\"\"\"\n");
    if plan.needs_rates {
        out.push_str("    dy = rhs(t, y, p, k)\n");
    }
    let (lines, cells) = dialect::row(plan, py);
    body(&mut out, &lines);
    out.push_str(&format!("    return [{}]\n\n\n", cells.join(", ")));
    out
}

/// The output grid, the run and the CSV, with `STEM` for the program's name.
const MAIN: &str = r#"def output_times():
    """0, STEP, 2 STEP, ... and T_FINAL, the last exactly."""
    n = math.floor(T_FINAL / STEP * (1.0 + 1e-12))
    times = [i * STEP for i in range(n + 1)]
    if abs(times[n] - T_FINAL) > 1e-12 * T_FINAL:
        times.append(T_FINAL)
    else:
        times[n] = T_FINAL
    return times


def main(argv):
    """STEM [OUT.csv]: writes the run's rows to OUT.csv (default: STEM.csv beside the program)."""
    for names, values, what in ((P_NAMES, P0, "parameter"), (Y_NAMES, Y0, "state")):
        for name, value in zip(names, values):
            if math.isnan(value):
                sys.exit(f"{NAME}: {what} {name} has no value: give it in the model file's INPUT and regenerate")
    if OPEN_INPUTS:
        print(f"{NAME}: warning: {', '.join(OPEN_INPUTS)} (inputs the model leaves open) are 0 in this run",
              file=sys.stderr)
    path = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), NAME + ".csv")
    p = P0
    k = constants(p)
    times = output_times()
    ys = np.array(Y0, dtype=float).reshape(-1, 1)
    if len(times) > 1:
        sol = solve_ivp(lambda t, y: rhs(t, y, p, k), (0.0, T_FINAL), ys[:, 0], method="DOP853", t_eval=times,
                        rtol=RTOL, atol=ATOL)
        if not sol.success:
            sys.exit(f"{NAME}: the integration stopped at t = {sol.t[-1] if len(sol.t) else 0.0}: {sol.message}")
        ys = sol.y
    tmp = path + ".partial"
    try:
        with open(tmp, "w") as out:
            out.write(HEADER + "\n")
            for i, t in enumerate(times):
                values = row(t, ys[:, i], p, k)
                bad = [j for j, v in enumerate(values) if not math.isfinite(v)]
                if bad:
                    raise ValueError(f"column {bad[0] + 2} of the row at t = {t!r} is not finite")
                out.write(",".join(repr(float(v)) for v in [t] + values) + "\n")
"#;

/// The end of `main`: `tmp` renamed to `path`, or removed and the run stopped; the entry point.
pub(super) const CLOSE_OUTPUT: &str = r#"        os.replace(tmp, path)
    except (OSError, ValueError) as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        sys.exit(f"{NAME}: {path} not written: {e}")


if __name__ == "__main__":
    main(sys.argv)
"#;
