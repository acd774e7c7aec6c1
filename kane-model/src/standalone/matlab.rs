//! A standalone MATLAB function file (also run by GNU Octave): in comes a [`Plan`]; out goes
//! one `.m` file whose main function integrates with `ode45` and writes the CSV, with the
//! model's `constants`, `rhs` and `row` as subfunctions.

use crate::expr::Func;
use crate::program::ir::Input;

use super::dialect::{self, single_quoted, Dialect};
use super::plan::Plan;
use super::{comment_lines, Program};

/// MATLAB's spelling (one-based indices).
pub(super) struct Matlab {
    /// Coordinates before speeds in the state.
    pub(super) n_coordinates: usize,
}

impl Dialect for Matlab {
    fn input(&self, input: Input) -> String {
        dialect::array_read(input, self.n_coordinates, 1, ("(", ")"), "NaN")
    }
    fn number(&self, x: f64) -> String {
        dialect::shortest(x)
    }
    fn powi(&self, a: &str, k: i32) -> String {
        match k {
            2 => format!("{a} * {a}"),
            _ => format!("{a}^({k})"),
        }
    }
    fn powf(&self, a: &str, b: &str) -> String {
        format!("{a}^{b}")
    }
    fn func(&self, f: Func, a: &str) -> String {
        format!("{}({a})", dialect::common_name(f))
    }
    fn atan2(&self, a: &str, b: &str) -> String {
        format!("atan2({a}, {b})")
    }
    fn assign(&self, name: &str, value: &str) -> String {
        format!("{name} = {value};")
    }
    fn nan(&self) -> String {
        "NaN".into()
    }
}

/// The MATLAB program of `plan`, its file named `stem`.
pub(super) fn program(plan: &Plan<'_>, stem: &str, about: &Program) -> String {
    let m = Matlab { n_coordinates: plan.info.n_coordinates };
    let mut out = format!("function {stem}(out)\n");
    let run =
        format!("{stem}() in MATLAB or Octave writes {stem}.csv beside this file; {stem}(OUT) writes OUT.");
    out.push_str(&comment_lines(&about.header_lines(&run, plan.once), "% ", "% ", ""));
    out.push_str(&main_body(plan, stem));
    out.push_str(&functions(plan, &m));
    out
}

/// A MATLAB column vector of `values` (NaN where not finite).
pub(super) fn vector(values: &[f64]) -> String {
    let items: Vec<String> =
        values.iter().map(|v| if v.is_finite() { dialect::shortest(*v) } else { "NaN".into() }).collect();
    format!("[{}]'", items.join("; "))
}

/// A MATLAB cell array of strings.
pub(super) fn names(values: &[&str]) -> String {
    let items: Vec<String> = values.iter().map(|v| single_quoted(v)).collect();
    format!("{{{}}}", items.join(", "))
}

/// The values, settings, run and CSV of the main function.
fn main_body(plan: &Plan<'_>, stem: &str) -> String {
    let info = plan.info;
    let s = plan.settings;
    let open: Vec<&str> = info.open_inputs.iter().map(|i| info.param_names[*i]).collect();
    let mut out = String::new();
    out.push_str("% The file's INPUT values (internal units: angles in radians); NaN where it gives none.\n");
    out.push_str(&format!("p = {};\np_names = {};\n", vector(&plan.start_params()), names(info.param_names)));
    out.push_str(&format!("y0 = {};\ny_names = {};\n", vector(&plan.initial), names(info.state_names)));
    out.push_str(&format!(
        "open_inputs = {};\nheader = {};\n",
        single_quoted(&open.join(", ")),
        single_quoted(&plan.header())
    ));
    out.push_str(&format!(
        "t_final = {}; step = {}; rtol = {}; atol = {};\n",
        dialect::shortest(s.t_final),
        dialect::shortest(s.output_step),
        dialect::shortest(s.rtol),
        dialect::shortest(s.atol)
    ));
    out.push_str(&MAIN.replace("% OPEN_OUTPUT\n", OPEN_OUTPUT).replace("STEM", stem));
    out
}

fn body(out: &mut String, lines: &[String]) {
    lines.iter().for_each(|l| out.push_str(&format!("  {l}\n")));
}

/// The subfunctions `constants`, `rhs` and `row`.
fn functions(plan: &Plan<'_>, m: &Matlab) -> String {
    let p = plan.program;
    let mut out = String::new();
    let results_into = |out: &mut String, into: &str, results: &[String]| {
        out.push_str(&format!("  {into} = zeros({}, 1);\n", results.len()));
        for (i, r) in results.iter().enumerate() {
            out.push_str(&format!("  {into}({}) = {r};\n", i + 1));
        }
    };
    let (lines, results) = dialect::print(&p.param_constants, m, "c");
    out.push_str(
        "\nfunction k = constants(p)\n  % The parameter-only quantities of p (once per parameter set).\n",
    );
    body(&mut out, &lines);
    results_into(&mut out, "k", &results);
    out.push_str("end\n");
    let (lines, results) = dialect::print(&p.rhs, m, "v");
    out.push_str("\nfunction dy = rhs(t, y, p, k)\n  % dy = f(t, y): coordinates' rates, then speeds' rates; k = constants(p).\n");
    body(&mut out, &lines);
    results_into(&mut out, "dy", &results);
    out.push_str("end\n");
    out.push_str("\nfunction r = row(t, y, p, k)\n  % One written row after t: each column in its unit.\n");
    if plan.needs_rates {
        out.push_str("  dy = rhs(t, y, p, k);\n");
    }
    out.push_str(&format!("  r = zeros(1, {});\n", plan.columns.len()));
    let (lines, cells) = dialect::row(plan, m);
    body(&mut out, &lines);
    for (col, cell) in cells.iter().enumerate() {
        out.push_str(&format!("  r({}) = {cell};\n", col + 1));
    }
    out.push_str("end\n");
    out
}

/// The checks, the integration and the CSV, with `STEM` for the program's name.
/// The lines that open `out.partial` as `fid` and write the header, or stop.
pub(super) const OPEN_OUTPUT: &str = r#"tmp = [out, '.partial'];
fid = fopen(tmp, 'w');
if fid < 0
  error('STEM: %s cannot be written', tmp);
end
fprintf(fid, '%s\n', header);
"#;

const MAIN: &str = r#"for i = 1:numel(p)
  if isnan(p(i))
    error('STEM: parameter %s has no value: give it in the model file''s INPUT and regenerate', p_names{i});
  end
end
for i = 1:numel(y0)
  if isnan(y0(i))
    error('STEM: state %s has no initial value: give it in the model file''s INPUT and regenerate', y_names{i});
  end
end
if ~isempty(open_inputs)
  fprintf(2, 'STEM: warning: %s (inputs the model leaves open) are 0 in this run\n', open_inputs);
end
if nargin < 1
  out = fullfile(fileparts(mfilename('fullpath')), 'STEM.csv');
end
% Output times 0, step, 2 step, ... and t_final, the last exactly.
n = floor(t_final / step * (1 + 1e-12));
times = (0:n) * step;
if abs(times(end) - t_final) > 1e-12 * t_final
  times(end + 1) = t_final;
else
  times(end) = t_final;
end
k = constants(p);
if numel(times) == 1
  % A run of length 0: the row at the INPUT values.
  ys = y0(:)';
else
  % ode45 returns every step for a span of two times: ask for the middle too, and drop it.
  span = times;
  if numel(span) == 2
    span = [times(1), mean(times), times(2)];
  end
  options = odeset('RelTol', rtol, 'AbsTol', atol);
  [ts, ys] = ode45(@(t, y) rhs(t, y, p, k), span, y0, options);
  if numel(span) == 3 && numel(times) == 2
    ts = ts([1, 3]); ys = ys([1, 3], :);
  end
  if numel(ts) ~= numel(times)
    error('STEM: the integration stopped at t = %.17g', ts(end));
  end
end
% OPEN_OUTPUT
for i = 1:numel(times)
  r = row(times(i), ys(i, :)', p, k);
  bad = find(~isfinite(r), 1);
  if ~isempty(bad)
    fclose(fid); delete(tmp);
    error('STEM: column %d of the row at t = %.17g is not finite', bad + 1, times(i));
  end
  fprintf(fid, '%.17g', times(i));
  fprintf(fid, ',%.17g', r);
  fprintf(fid, '\n');
end
fclose(fid);
movefile(tmp, out, 'f');
end
"#;
