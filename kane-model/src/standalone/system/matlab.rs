//! A CODE ALGEBRAIC or NONLINEAR system as a MATLAB function file (also run by GNU Octave):
//! the residuals and Jacobian as a subfunction, LU with partial pivoting and the Newton
//! iteration of `kane solve`, the solution printed and written as CSV.

use super::super::comment_lines;
use super::super::dialect::{self, shortest, single_quoted};
use super::super::matlab::{names, vector, Matlab, OPEN_OUTPUT};
use super::{Program, SystemPlan, SINGULAR_PIVOT, TOLERANCE};

/// The MATLAB program of `plan`, its file named `stem`.
pub(super) fn program(plan: &SystemPlan, stem: &str, about: &Program) -> String {
    let m = Matlab { n_coordinates: 0 };
    let n = plan.unknowns.len();
    let mut out = format!("function {stem}(out)\n");
    let run =
        format!("{stem}() in MATLAB or Octave writes {stem}.csv beside this file; {stem}(OUT) writes OUT.");
    out.push_str(&comment_lines(&about.system_header_lines(plan, &run), "% ", "% ", ""));
    let (p_names, x_names) = (as_str(&plan.names), as_str(&plan.unknowns));
    out.push_str("% The file's INPUT values (internal units: angles in radians); NaN where it gives none.\n");
    out.push_str(&format!("p = {};\np_names = {};\n", vector(&plan.values), names(&p_names)));
    out.push_str(&format!("x_names = {};\nheader = {};\n", names(&x_names), single_quoted(&plan.header())));
    let (lines, results) = dialect::print(&plan.section, &m, "v");
    if plan.evaluation {
        out.push_str(&CHECKS.replace("STEM", stem));
        out.push_str(&EVALUATE.replace("STEM", stem));
    } else {
        out.push_str(&format!(
            "x = {};\nsteps = {}; damped = {}; check_start = {};\ntolerance = {}; singular = {};\n",
            vector(&plan.start),
            plan.steps(),
            plan.damped(),
            plan.checked_start(),
            shortest(TOLERANCE),
            shortest(SINGULAR_PIVOT)
        ));
        out.push_str(&CHECKS.replace("STEM", stem));
        out.push_str(&NEWTON.replace("STEM", stem));
    }
    out.push_str(&WRITE.replace("% OPEN_OUTPUT\n", OPEN_OUTPUT).replace("STEM", stem));
    if plan.evaluation {
        out.push_str("\nfunction x = values(p)\n  % The quantities x at the parameters p.\n  t = 0;\n");
        lines.iter().for_each(|l| out.push_str(&format!("  {l}\n")));
        out.push_str(&format!("  x = zeros({n}, 1);\n"));
        for (i, v) in results.iter().enumerate() {
            out.push_str(&format!("  x({}) = {v};\n", i + 1));
        }
    } else {
        out.push_str("\nfunction [r, jac] = equations(y, p)\n  % The residuals r and the Jacobian jac at the unknowns y.\n  t = 0;\n");
        lines.iter().for_each(|l| out.push_str(&format!("  {l}\n")));
        out.push_str(&format!("  r = zeros({n}, 1);\n  jac = zeros({n}, {n});\n"));
        for (i, v) in results.iter().enumerate() {
            if i < n {
                out.push_str(&format!("  r({}) = {v};\n", i + 1));
            } else {
                out.push_str(&format!("  jac({}, {}) = {v};\n", (i - n) / n + 1, (i - n) % n + 1));
            }
        }
    }
    out.push_str("end\n");
    out.push_str(HELPERS);
    out
}

fn as_str(names: &[String]) -> Vec<&str> {
    names.iter().map(String::as_str).collect()
}

/// The parameters' checks and the output file's name, with `STEM` for the program's name.
const CHECKS: &str = r#"p = p(:);
for i = 1:numel(p)
  if isnan(p(i))
    error('STEM: %s has no value: give it in the model file''s INPUT and regenerate', p_names{i});
  end
end
if nargin < 1
  out = fullfile(fileparts(mfilename('fullpath')), 'STEM.csv');
end
"#;

/// The iteration from the file's starting values, with `STEM` for the program's name.
const NEWTON: &str = r#"x = x(:);
for i = 1:numel(x)
  if check_start && isnan(x(i))
    error('STEM: %s has no starting value: give it in the model file''s INPUT and regenerate', x_names{i});
  end
end
[r, jac] = equations(x, p);
scale = 1 + largest(jac) * max(largest(x), 1);
converged = false;
for iteration = 0:steps - 1
  if ~isfinite(largest(r))
    error('STEM: the equations are not finite at %s', at(x_names, x));
  end
  if largest(r) <= tolerance * scale && iteration > 0
    converged = true;
    break;
  end
  [L, U, P] = lu(jac);
  if ~(min(abs(diag(U))) > singular * largest(jac))
    error('STEM: the Jacobian of the equations is singular at %s', at(x_names, x));
  end
  dx = -(U \ (L \ (P * r)));
  step = 1;
  while true
    trial = x + step * dx;
    [rt, jt] = equations(trial, p);
    if largest(rt) < largest(r) || step < 1e-4 || ~damped
      break;
    end
    step = step / 2;
  end
  x = trial; r = rt; jac = jt;
end
if ~converged && damped && ~(largest(r) <= tolerance * scale)
  error('STEM: Newton''s method did not converge in %d steps: the largest residual is %g at %s', ...
        steps, largest(r), at(x_names, x));
end
"#;

/// An evaluation: the quantities at the parameters, each finite.
const EVALUATE: &str = r#"x = values(p);
for i = 1:numel(x)
  if ~isfinite(x(i))
    error('STEM: %s is %g at the file''s INPUT values', x_names{i}, x(i));
  end
end
"#;

/// The solution printed and written as CSV, with `STEM` for the program's name.
const WRITE: &str = r#"% OPEN_OUTPUT
for i = 1:numel(x)
  fprintf('%s = %.17g\n', x_names{i}, x(i));
  if i > 1
    fprintf(fid, ',');
  end
  fprintf(fid, '%.17g', x(i));
end
fprintf(fid, '\n');
fclose(fid);
movefile(tmp, out, 'f');
end
"#;

/// `largest` and `at`.
const HELPERS: &str = r#"
function m = largest(v)
  % The largest magnitude in v, NaN if one is not a number.
  if any(isnan(v(:)))
    m = NaN;
  else
    m = max([0; abs(v(:))]);
  end
end

function s = at(names, x)
  % 'X = 1, Y = 2'.
  parts = cell(1, numel(x));
  for i = 1:numel(x)
    parts{i} = sprintf('%s = %.17g', names{i}, x(i));
  end
  s = strjoin(parts, ', ');
end
"#;
