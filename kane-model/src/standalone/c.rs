//! A standalone C99 program: in comes a [`Plan`]; out goes one `.c` file with the model's
//! `constants`, `rhs` and `row` functions and a driver (an embedded Runge-Kutta 5(4) method
//! with error control, stepping onto each output time) that writes the CSV. It needs `-lm` only.

use crate::expr::Func;
use crate::program::ir::Input;

use super::dialect::{self, Dialect};
use super::plan::Plan;
use super::{comment_lines, Program};

/// C's spelling.
pub(super) struct C {
    /// Coordinates before speeds in the state.
    pub(super) n_coordinates: usize,
}

impl Dialect for C {
    fn input(&self, input: Input) -> String {
        dialect::array_read(input, self.n_coordinates, 0, ("[", "]"), "NAN")
    }
    fn number(&self, x: f64) -> String {
        dialect::shortest(x)
    }
    fn powi(&self, a: &str, k: i32) -> String {
        dialect::powi_by_pow(a, k, "pow")
    }
    fn powf(&self, a: &str, b: &str) -> String {
        format!("pow({a}, {b})")
    }
    fn func(&self, f: Func, a: &str) -> String {
        match f {
            Func::Abs => format!("fabs({a})"),
            Func::Sign => format!("(double)(({a} > 0.0) - ({a} < 0.0))"),
            other => format!("{}({a})", dialect::common_name(other)),
        }
    }
    fn atan2(&self, a: &str, b: &str) -> String {
        format!("atan2({a}, {b})")
    }
    fn assign(&self, name: &str, value: &str) -> String {
        format!("const double {name} = {value};")
    }
    fn nan(&self) -> String {
        "NAN".into()
    }
}

/// The C program of `plan`, its file named `stem`.
pub(super) fn program(plan: &Plan<'_>, stem: &str, about: &Program) -> String {
    let c = C { n_coordinates: plan.info.n_coordinates };
    let name = about.identifier.as_str();
    let mut out = String::new();
    out.push_str(&comment_lines(
        &about.header_lines(&format!("cc -O2 -o {stem} {stem}.c -lm"), plan.once),
        "/* ",
        " * ",
        " */",
    ));
    out.push_str("#include <math.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n");
    let (ny, np) = (plan.info.state_names.len(), plan.params.len());
    let nk = plan.program.param_constants.results.len().max(1);
    out.push_str(&format!("enum {{ NY = {ny}, NP = {np}, NK = {nk}, NCOL = {} }};\n\n", plan.columns.len()));
    out.push_str(&functions(plan, &c, name));
    out.push_str(&driver(plan, stem, name));
    out
}

/// `NAME_constants`, `NAME_rhs` and `NAME_row`.
pub(super) fn functions(plan: &Plan<'_>, c: &C, name: &str) -> String {
    let p = plan.program;
    let mut out = String::new();
    let (lines, results) = dialect::print(&p.param_constants, c, "c");
    out.push_str("/* The parameter-only quantities of p (once per parameter set). */\n");
    out.push_str(&format!("void {name}_constants(const double p[NP], double k[NK]) {{\n"));
    push_body(&mut out, &lines, &results, "k");
    out.push_str("}\n\n");
    let (lines, results) = dialect::print(&p.rhs, c, "v");
    out.push_str("/* dy = f(t, y): coordinates' rates, then speeds' rates; k = constants of p. */\n");
    out.push_str(&format!(
        "void {name}_rhs(double t, const double y[NY], const double p[NP], const double k[NK], double dy[NY]) {{\n"
    ));
    out.push_str("    (void)t; (void)y; (void)p; (void)k;\n");
    push_body(&mut out, &lines, &results, "dy");
    out.push_str("}\n\n");
    out.push_str("/* One written row after t: each column in its unit. */\n");
    out.push_str(&format!(
        "void {name}_row(double t, const double y[NY], const double p[NP], const double k[NK], double row[NCOL]) {{\n"
    ));
    out.push_str("    (void)t; (void)p;\n");
    if plan.needs_rates {
        out.push_str(&format!("    double dy[NY];\n    {name}_rhs(t, y, p, k, dy);\n"));
    } else {
        out.push_str("    (void)k;\n");
    }
    let (lines, cells) = dialect::row(plan, c);
    lines.iter().for_each(|l| out.push_str(&format!("    {l}\n")));
    for (col, cell) in cells.iter().enumerate() {
        out.push_str(&format!("    row[{col}] = {cell};\n"));
    }
    out.push_str("}\n\n");
    out
}

fn push_body(out: &mut String, lines: &[String], results: &[String], into: &str) {
    lines.iter().for_each(|l| out.push_str(&format!("    {l}\n")));
    for (i, r) in results.iter().enumerate() {
        out.push_str(&format!("    {into}[{i}] = {r};\n"));
    }
}

/// A C array literal of `values` (NAN where not finite).
pub(super) fn array(values: &[f64]) -> String {
    if values.is_empty() {
        return "{ 0.0 }".into();
    }
    let items: Vec<String> =
        values.iter().map(|v| if v.is_finite() { dialect::shortest(*v) } else { "NAN".into() }).collect();
    format!("{{ {} }}", items.join(", "))
}

/// A C array literal of strings.
pub(super) fn strings(values: &[&str]) -> String {
    if values.is_empty() {
        return "{ \"\" }".into();
    }
    let items: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
    format!("{{ {} }}", items.join(", "))
}

/// The values, settings and `main`.
fn driver(plan: &Plan<'_>, stem: &str, name: &str) -> String {
    let info = plan.info;
    let s = plan.settings;
    let open: Vec<&str> = info.open_inputs.iter().map(|i| info.param_names[*i]).collect();
    let mut out = String::new();
    out.push_str(
        "/* The file's INPUT values (internal units: angles in radians); NAN where it gives none. */\n",
    );
    out.push_str(&format!("static const double P0[NP] = {};\n", array(&plan.start_params())));
    out.push_str(&format!("static const char *const P_NAMES[NP] = {};\n", strings(info.param_names)));
    out.push_str(&format!("static const double Y0[NY] = {};\n", array(&plan.initial)));
    out.push_str(&format!("static const char *const Y_NAMES[NY] = {};\n", strings(info.state_names)));
    out.push_str(&format!(
        "static const char *const OPEN_INPUTS = {:?};\nstatic const char *const HEADER = {:?};\n",
        open.join(", "),
        plan.header()
    ));
    out.push_str(&format!(
        "static const double T_FINAL = {}, STEP = {}, RTOL = {}, ATOL = {};\n\n",
        dialect::shortest(s.t_final),
        dialect::shortest(s.output_step),
        dialect::shortest(s.rtol),
        dialect::shortest(s.atol)
    ));
    out.push_str(&INTEGRATOR.replace("MODEL", name));
    out.push_str(
        &MAIN.replace("    /* OPEN_OUTPUT */\n", OPEN_OUTPUT).replace("MODEL", name).replace("STEM", stem),
    );
    out
}

/// The integrator, with `MODEL` for the functions' prefix.
pub(super) const INTEGRATOR: &str = r#"/* Dormand-Prince 5(4): one step of size h from (t, y) into y1, its error norm returned. */
static double dopri_step(double t, const double y[NY], const double f0[NY], double h, const double p[NP],
                         const double k[NK], const double tol[2], double y1[NY], double f1[NY]) {
    static const double A[6][6] = {
        {1.0 / 5},
        {3.0 / 40, 9.0 / 40},
        {44.0 / 45, -56.0 / 15, 32.0 / 9},
        {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
        {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
        {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
    static const double C[6] = {1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
    static const double E[7] = {71.0 / 57600, 0.0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525,
                                -1.0 / 40};
    double stages[7][NY], yi[NY];
    memcpy(stages[0], f0, sizeof stages[0]);
    for (int s = 0; s < 6; s++) {
        for (int i = 0; i < NY; i++) {
            double sum = 0.0;
            for (int j = 0; j <= s; j++) sum += A[s][j] * stages[j][i];
            yi[i] = y[i] + h * sum;
        }
        MODEL_rhs(t + C[s] * h, yi, p, k, stages[s + 1]);
    }
    memcpy(y1, yi, sizeof yi);
    memcpy(f1, stages[6], sizeof stages[6]);
    double norm = 0.0;
    for (int i = 0; i < NY; i++) {
        double e = 0.0;
        for (int j = 0; j < 7; j++) e += E[j] * stages[j][i];
        double scale = tol[1] + tol[0] * fmax(fabs(y[i]), fabs(y1[i]));
        norm += (h * e / scale) * (h * e / scale);
    }
    return NY > 0 ? sqrt(norm / NY) : 0.0;
}

/* Integrates from (t, y) to t_end, f = rhs at (t, y), h the step to try (updated), tol = {rtol,
 * atol}; 0 on success. */
static int advance(double *t, double y[NY], double f[NY], double t_end, double *h, const double p[NP],
                   const double k[NK], const double tol[2]) {
    double y1[NY], f1[NY];
    while (*t < t_end) {
        double step = fmin(*h, t_end - *t);
        if (!(step > 1e-14 * fmax(1.0, fabs(*t)))) return 1;
        double err = dopri_step(*t, y, f, step, p, k, tol, y1, f1);
        if (!isfinite(err)) err = 1e10;
        double factor = err > 0.0 ? 0.9 * pow(err, -0.2) : 5.0;
        factor = fmin(5.0, fmax(0.2, factor));
        if (err <= 1.0) {
            *t = (t_end - *t - step <= 1e-14 * fmax(1.0, fabs(t_end))) ? t_end : *t + step;
            memcpy(y, y1, sizeof y1);
            memcpy(f, f1, sizeof f1);
            if (step == *h || factor < 1.0) *h = step * factor;
        } else {
            *h = step * fmin(1.0, factor);
        }
    }
    return 0;
}
"#;

/// The CSV writer, the run and `main`, with `MODEL` for the functions' prefix and `STEM` for
/// the file's.
/// The lines of `main` that open `OUT.csv.partial` as `out` (default: STEM.csv beside the
/// program), or return 1.
pub(super) const OPEN_OUTPUT: &str = r#"    char path[4096], tmp[4200];
    if (argc > 1) {
        snprintf(path, sizeof path, "%s", argv[1]);
    } else {
        const char *slash = strrchr(argv[0], '/');
        int dir = slash ? (int)(slash - argv[0]) + 1 : 0;
        snprintf(path, sizeof path, "%.*sSTEM.csv", dir, argv[0]);
    }
    snprintf(tmp, sizeof tmp, "%s.partial", path);
    FILE *out = fopen(tmp, "w");
    if (!out) {
        perror(tmp);
        return 1;
    }
"#;

const MAIN: &str = r#"
/* x in the fewest digits that read back as x. */
static void put(FILE *out, double x) {
    char text[32];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(text, sizeof text, "%.*g", digits, x);
        if (strtod(text, NULL) == x) break;
    }
    fputs(text, out);
}

static int write_row(FILE *out, double t, const double y[NY], const double p[NP], const double k[NK]) {
    double row[NCOL > 0 ? NCOL : 1];
    MODEL_row(t, y, p, k, row);
    put(out, t);
    for (int i = 0; i < NCOL; i++) {
        if (!isfinite(row[i])) {
            fprintf(stderr, "STEM: column %d of the row at t = %.17g is not finite\n", i + 2, t);
            return 1;
        }
        fputc(',', out);
        put(out, row[i]);
    }
    fputc('\n', out);
    return 0;
}

/* Integrates from t = 0 to T_FINAL and writes a row at every output time. */
static int run(FILE *out, const double p[NP]) {
    double k[NK], y[NY], f[NY], t = 0.0;
    const double tol[2] = {RTOL, ATOL};
    MODEL_constants(p, k);
    memcpy(y, Y0, sizeof y);
    MODEL_rhs(t, y, p, k, f);
    double h = fmin(STEP, 1e-3 * fmax(T_FINAL, 1e-300));
    fprintf(out, "%s\n", HEADER);
    if (write_row(out, t, y, p, k)) return 1;
    long n = (long)floor(T_FINAL / STEP * (1.0 + 1e-12));
    for (long i = 1; i <= n + 1; i++) {
        double target = (double)i * STEP;
        if (i == n && fabs(target - T_FINAL) <= 1e-12 * T_FINAL) target = T_FINAL;
        if (i == n + 1) {
            if (t >= T_FINAL) break;
            target = T_FINAL;
        }
        if (advance(&t, y, f, target, &h, p, k, tol)) {
            fprintf(stderr, "STEM: the step size fell to nothing at t = %.17g: the solution is singular there\n", t);
            return 1;
        }
        if (write_row(out, t, y, p, k)) return 1;
    }
    return 0;
}

/* STEM [OUT.csv]: writes the run's rows to OUT.csv (default: STEM.csv beside the program). */
int main(int argc, char **argv) {
    for (int i = 0; i < NP; i++)
        if (isnan(P0[i])) {
            fprintf(stderr, "STEM: parameter %s has no value: give it in the model file's INPUT and regenerate\n",
                    P_NAMES[i]);
            return 2;
        }
    for (int i = 0; i < NY; i++)
        if (isnan(Y0[i])) {
            fprintf(stderr, "STEM: state %s has no initial value: give it in the model file's INPUT and regenerate\n",
                    Y_NAMES[i]);
            return 2;
        }
    if (OPEN_INPUTS[0]) fprintf(stderr, "STEM: warning: %s (inputs the model leaves open) are 0 in this run\n", OPEN_INPUTS);
    /* OPEN_OUTPUT */
    int failed = run(out, P0);
    failed |= fclose(out) != 0;
    if (failed || rename(tmp, path) != 0) {
        remove(tmp);
        fprintf(stderr, "STEM: %s not written\n", path);
        return 1;
    }
    return 0;
}
"#;
