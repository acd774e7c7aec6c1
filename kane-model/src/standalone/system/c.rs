//! A CODE ALGEBRAIC or NONLINEAR system as a C99 program: the residuals and Jacobian as one
//! function, Gaussian elimination with partial pivoting and the Newton iteration of
//! `kane solve`, the solution printed and written as CSV. It needs `-lm` only.

use super::super::c::{array, strings, C, OPEN_OUTPUT};
use super::super::comment_lines;
use super::super::dialect::{self, shortest};
use super::{Program, SystemPlan, SINGULAR_PIVOT, TOLERANCE};

/// The C program of `plan`, its file named `stem`.
pub(super) fn program(plan: &SystemPlan, stem: &str, about: &Program) -> String {
    let c = C { n_coordinates: 0 };
    let name = about.identifier.as_str();
    let (n, np) = (plan.unknowns.len(), plan.names.len());
    let mut out = comment_lines(
        &about.system_header_lines(plan, &format!("cc -O2 -o {stem} {stem}.c -lm && ./{stem} [OUT.csv]")),
        "/* ",
        " * ",
        " */",
    );
    out.push_str("#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n");
    out.push_str(&format!("enum {{ NX = {n}, NP = {} }};\n\n", np.max(1)));
    let (lines, results) = dialect::print(&plan.section, &c, "v");
    if plan.evaluation {
        out.push_str("/* The quantities x at the parameters p. */\n");
        out.push_str(&format!("void {name}_values(const double p[NP], double x[NX]) {{\n"));
        out.push_str("    const double t = 0.0;\n    (void)t; (void)p;\n");
    } else {
        out.push_str("/* The residuals r and the Jacobian jac (row by row) at the unknowns y. */\n");
        out.push_str(&format!(
            "void {name}_system(const double y[NX], const double p[NP], double r[NX], double jac[NX * NX]) {{\n"
        ));
        out.push_str("    const double t = 0.0;\n    (void)t; (void)y; (void)p;\n");
    }
    lines.iter().for_each(|l| out.push_str(&format!("    {l}\n")));
    for (i, v) in results.iter().enumerate() {
        let (into, at) = match (plan.evaluation, i < n) {
            (true, _) => ("x", i),
            (false, true) => ("r", i),
            (false, false) => ("jac", i - n),
        };
        out.push_str(&format!("    {into}[{at}] = {v};\n"));
    }
    out.push_str("}\n\n");
    let names: Vec<&str> = plan.names.iter().map(String::as_str).collect();
    let unknowns: Vec<&str> = plan.unknowns.iter().map(String::as_str).collect();
    out.push_str(
        "/* The file's INPUT values (internal units: angles in radians); NAN where it gives none. */\n",
    );
    out.push_str(&format!("static const double P0[NP] = {};\n", array(&plan.values)));
    out.push_str(&format!("static const char *const P_NAMES[NP] = {};\n", strings(&names)));
    out.push_str(&format!("static const char *const X_NAMES[NX] = {};\n", strings(&unknowns)));
    out.push_str(&format!("static const char *const HEADER = {:?};\n", plan.header()));
    let named = |text: &str| text.replace("MODEL", name).replace("STEM", stem);
    if plan.evaluation {
        out.push_str(&named(EVALUATE));
    } else {
        out.push_str(&format!("static const double X0[NX] = {};\n", array(&plan.start)));
        out.push_str(&format!(
            "enum {{ STEPS = {}, DAMPED = {}, CHECK_START = {} }};\n",
            plan.steps(),
            i32::from(plan.damped()),
            i32::from(plan.checked_start())
        ));
        out.push_str(&format!(
            "static const double TOLERANCE = {}, SINGULAR = {};\n",
            shortest(TOLERANCE),
            shortest(SINGULAR_PIVOT)
        ));
        out.push_str(&named(SOLVER));
    }
    out.push_str(&named(&MAIN.replace("    /* OPEN_OUTPUT */\n", OPEN_OUTPUT)));
    out
}

/// The elimination and the iteration, with `MODEL` for the functions' prefix and `STEM` for the
/// file's.
const SOLVER: &str = r#"
/* The largest magnitude in v, NAN if one is not a number. */
static double largest(const double *v, int n) {
    double m = 0.0;
    for (int i = 0; i < n; i++) {
        if (isnan(v[i])) return NAN;
        m = fmax(m, fabs(v[i]));
    }
    return m;
}

/* Solves a x = b in place of b (a row by row, overwritten) by partial pivoting; 1 if singular. */
static int eliminate(double a[NX * NX], double b[NX]) {
    double big = largest(a, NX * NX);
    for (int c = 0; c < NX; c++) {
        int pivot = c;
        for (int r = c + 1; r < NX; r++)
            if (fabs(a[r * NX + c]) > fabs(a[pivot * NX + c])) pivot = r;
        if (!(fabs(a[pivot * NX + c]) > SINGULAR * big)) return 1;
        for (int j = 0; j < NX && pivot != c; j++) {
            double s = a[c * NX + j];
            a[c * NX + j] = a[pivot * NX + j];
            a[pivot * NX + j] = s;
        }
        double s = b[c];
        b[c] = b[pivot];
        b[pivot] = s;
        for (int r = c + 1; r < NX; r++) {
            double f = a[r * NX + c] / a[c * NX + c];
            for (int j = c; j < NX; j++) a[r * NX + j] -= f * a[c * NX + j];
            b[r] -= f * b[c];
        }
    }
    for (int c = NX - 1; c >= 0; c--) {
        double s = b[c];
        for (int j = c + 1; j < NX; j++) s -= a[c * NX + j] * b[j];
        b[c] = s / a[c * NX + c];
    }
    return 0;
}

static void print_at(const double x[NX]) {
    for (int i = 0; i < NX; i++) fprintf(stderr, "%s%s = %.17g", i ? ", " : "", X_NAMES[i], x[i]);
    fputc('\n', stderr);
}

/* Newton's method from x (the solution on return); 0 when it converges. */
static int newton(const double p[NP], double x[NX]) {
    double r[NX], jac[NX * NX], trial[NX], rt[NX], jt[NX * NX], a[NX * NX], dx[NX];
    MODEL_system(x, p, r, jac);
    double scale = 1.0 + largest(jac, NX * NX) * fmax(largest(x, NX), 1.0);
    for (int iteration = 0; iteration < STEPS; iteration++) {
        if (!isfinite(largest(r, NX))) {
            fprintf(stderr, "STEM: the equations are not finite at ");
            print_at(x);
            return 1;
        }
        if (largest(r, NX) <= TOLERANCE * scale && iteration > 0) return 0;
        memcpy(a, jac, sizeof a);
        for (int i = 0; i < NX; i++) dx[i] = -r[i];
        if (eliminate(a, dx)) {
            fprintf(stderr, "STEM: the Jacobian of the equations is singular at ");
            print_at(x);
            return 1;
        }
        for (double step = 1.0;; step /= 2.0) {
            for (int i = 0; i < NX; i++) trial[i] = x[i] + step * dx[i];
            MODEL_system(trial, p, rt, jt);
            if (largest(rt, NX) < largest(r, NX) || step < 1e-4 || !DAMPED) break;
        }
        memcpy(x, trial, sizeof trial);
        memcpy(r, rt, sizeof rt);
        memcpy(jac, jt, sizeof jt);
    }
    if (largest(r, NX) <= TOLERANCE * scale || !DAMPED) return 0;
    fprintf(stderr, "STEM: Newton's method did not converge in %d steps: the largest residual is %g at ", STEPS,
            largest(r, NX));
    print_at(x);
    return 1;
}

/* The solution from the file's starting values, in x; 0 when Newton's method converges, 2 when
   a starting value is missing. */
static int solve(const double p[NP], double x[NX]) {
    for (int i = 0; i < NX && CHECK_START; i++)
        if (isnan(X0[i])) {
            fprintf(stderr, "STEM: %s has no starting value: give it in the model file's INPUT and regenerate\n",
                    X_NAMES[i]);
            return 2;
        }
    memcpy(x, X0, sizeof X0);
    return newton(p, x);
}
"#;

/// `main`: the checks, the solve and the CSV, with `STEM` for the file's name.
const MAIN: &str = r#"
/* STEM [OUT.csv]: prints the solution and writes it to OUT.csv (default: STEM.csv beside the program). */
int main(int argc, char **argv) {
    static double x[NX];
    for (int i = 0; i < NP && P_NAMES[i][0]; i++)
        if (isnan(P0[i])) {
            fprintf(stderr, "STEM: %s has no value: give it in the model file's INPUT and regenerate\n", P_NAMES[i]);
            return 2;
        }
    int status = solve(P0, x);
    if (status) return status;
    /* OPEN_OUTPUT */
    fprintf(out, "%s\n", HEADER);
    for (int i = 0; i < NX; i++) {
        printf("%s = %.17g\n", X_NAMES[i], x[i]);
        fprintf(out, "%s%.17g", i ? "," : "", x[i]);
    }
    fputc('\n', out);
    if (fclose(out) != 0 || rename(tmp, path) != 0) {
        remove(tmp);
        fprintf(stderr, "STEM: %s not written\n", path);
        return 1;
    }
    return 0;
}
"#;

/// An evaluation's `solve`: the quantities at the parameters, each finite.
const EVALUATE: &str = r#"
/* The quantities at the parameters p, in x; 0 when each is finite. */
static int solve(const double p[NP], double x[NX]) {
    MODEL_values(p, x);
    for (int i = 0; i < NX; i++)
        if (!isfinite(x[i])) {
            fprintf(stderr, "STEM: %s is %g at the file's INPUT values\n", X_NAMES[i], x[i]);
            return 1;
        }
    return 0;
}
"#;
