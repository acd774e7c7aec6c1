//! A CODE ALGEBRAIC or NONLINEAR system as a Python program: the residuals and Jacobian as one
//! function, SciPy's LU with partial pivoting and the Newton iteration of `kane solve`, the
//! solution printed and written as CSV. It needs NumPy and SciPy.

use super::super::comment_lines;
use super::super::dialect::{self, shortest};
use super::super::python::{body, list, names, Python, CLOSE_OUTPUT, IMPORTS};
use super::{Program, SystemPlan, SINGULAR_PIVOT, TOLERANCE};

/// The Python program of `plan`, its file named `stem`.
pub(super) fn program(plan: &SystemPlan, stem: &str, about: &Program) -> String {
    let py = Python { n_coordinates: 0 };
    let n = plan.unknowns.len();
    let run = format!("python3 {stem}.py [OUT.csv]");
    let mut out = comment_lines(&about.system_header_lines(plan, &run), "# ", "# ", "");
    out.push_str(&IMPORTS.replace("import sys\n", "import sys\nimport warnings\n"));
    out.push_str("from scipy.linalg import lu_factor, lu_solve\n\n");
    let refs = |v: &[String]| -> String { names(&v.iter().map(String::as_str).collect::<Vec<_>>()) };
    out.push_str(&format!("NAME = {stem:?}\n"));
    out.push_str("# The file's INPUT values (internal units: angles in radians); nan where it gives none.\n");
    out.push_str(&format!("P0 = {}\nP_NAMES = {}\n", list(&plan.values), refs(&plan.names)));
    out.push_str(&format!("X_NAMES = {}\nHEADER = {:?}\n", refs(&plan.unknowns), plan.header()));
    let (lines, results) = dialect::print(&plan.section, &py, "v");
    if plan.evaluation {
        out.push_str(
            "\n\ndef values(p):\n    \"\"\"The quantities at the parameters p.\"\"\"\n    t = 0.0\n",
        );
        body(&mut out, &lines);
        out.push_str(&format!("    return np.array([{}], dtype=float)\n\n\n", results.join(", ")));
        out.push_str(EVALUATE);
    } else {
        out.push_str(&format!(
            "X0 = {}\nSTEPS, DAMPED, CHECK_START = {}, {}, {}\nTOLERANCE, SINGULAR = {}, {}\n\n\n",
            list(&plan.start),
            plan.steps(),
            if plan.damped() { "True" } else { "False" },
            if plan.checked_start() { "True" } else { "False" },
            shortest(TOLERANCE),
            shortest(SINGULAR_PIVOT)
        ));
        out.push_str("def equations(y, p):\n    \"\"\"The residuals and the Jacobian (rows) at the unknowns y.\"\"\"\n    t = 0.0\n");
        body(&mut out, &lines);
        let rows: Vec<String> =
            results[n..].chunks(n.max(1)).map(|row| format!("[{}]", row.join(", "))).collect();
        out.push_str(&format!(
            "    return np.array([{}], dtype=float), np.array([{}], dtype=float).reshape({n}, {n})\n\n\n",
            results[..n].join(", "),
            rows.join(", ")
        ));
        out.push_str(SOLVER);
    }
    out.push_str(&MAIN.replace("STEM", stem));
    out.push_str(CLOSE_OUTPUT);
    out
}

/// The iteration from the file's starting values.
const SOLVER: &str = r#"def largest(v):
    """The largest magnitude in v, nan if one is not a number."""
    v = np.abs(np.asarray(v, dtype=float)).ravel()
    return math.nan if np.isnan(v).any() else float(v.max(initial=0.0))


def at(x):
    """'X = 1, Y = 2'."""
    return ", ".join(f"{n} = {float(v)!r}" for n, v in zip(X_NAMES, x))


def evaluated(x, p):
    """The equations at x, or an exit naming where they cannot be evaluated."""
    try:
        return equations(x, p)
    except (ArithmeticError, ValueError) as e:
        sys.exit(f"{NAME}: the equations cannot be evaluated at {at(x)}: {e}")


def newton(p, x):
    """Newton's method from x; the solution, or an exit saying why there is none."""
    r, jac = evaluated(x, p)
    scale = 1.0 + largest(jac) * max(largest(x), 1.0)
    for iteration in range(STEPS):
        if not math.isfinite(largest(r)):
            sys.exit(f"{NAME}: the equations are not finite at {at(x)}")
        if largest(r) <= TOLERANCE * scale and iteration > 0:
            return x
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a singular matrix is reported below
            lu, pivots = lu_factor(jac, check_finite=False)
        if not np.min(np.abs(np.diag(lu))) > SINGULAR * largest(jac):
            sys.exit(f"{NAME}: the Jacobian of the equations is singular at {at(x)}")
        dx = -lu_solve((lu, pivots), r)
        step = 1.0
        while True:
            trial = x + step * dx
            rt, jt = evaluated(trial, p)
            if largest(rt) < largest(r) or step < 1e-4 or not DAMPED:
                break
            step /= 2.0
        x, r, jac = trial, rt, jt
    if largest(r) <= TOLERANCE * scale or not DAMPED:
        return x
    sys.exit(f"{NAME}: Newton's method did not converge in {STEPS} steps: the largest residual is "
             f"{largest(r):g} at {at(x)}")


def solve(p):
    """The solution from the file's starting values, or an exit saying why there is none."""
    for name, value in zip(X_NAMES, X0):
        if CHECK_START and math.isnan(value):
            missing(f"{name} has no starting value")
    return newton(p, np.array(X0, dtype=float))
"#;

/// An evaluation's `solve`: the quantities at the parameters, each finite.
const EVALUATE: &str = r#"def solve(p):
    """The quantities at the parameters p, or an exit naming one that cannot be evaluated."""
    try:
        x = values(p)
    except (ArithmeticError, ValueError) as e:
        sys.exit(f"{NAME}: the quantities cannot be evaluated at the file's INPUT values: {e}")
    for name, value in zip(X_NAMES, x):
        if not math.isfinite(value):
            sys.exit(f"{NAME}: {name} is {value} at the file's INPUT values")
    return x
"#;

/// The checks, the solve and the CSV, with `STEM` for the program's name.
const MAIN: &str = r#"

def missing(what):
    """Stops with status 2, saying what has no value and what to do."""
    print(f"{NAME}: {what}: give it in the model file's INPUT and regenerate", file=sys.stderr)
    sys.exit(2)


def main(argv):
    """STEM [OUT.csv]: prints the solution and writes it to OUT.csv (default: STEM.csv beside the program)."""
    for name, value in zip(P_NAMES, P0):
        if math.isnan(value):
            missing(f"{name} has no value")
    x = solve(np.array(P0, dtype=float))
    path = argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), NAME + ".csv")
    for name, value in zip(X_NAMES, x):
        print(f"{name} = {float(value)!r}")
    tmp = path + ".partial"
    try:
        with open(tmp, "w") as out:
            out.write(HEADER + "\n" + ",".join(repr(float(v)) for v in x) + "\n")
"#;
