//! A standalone Fortran program: in comes a [`Plan`]; out goes one program unit with the
//! model's `constants`, `rhs` and `row` as internal procedures and the same Dormand-Prince 5(4)
//! driver as the C program's. It is laid out in the format fixed and free form share (code from
//! column 7, lines of at most 72 columns, a continued line ending in `&` at column 73 and its
//! continuation starting with `&` in column 6), so one text compiles as `.f`, `.for` and `.f90`.

use crate::expr::Func;
use crate::program::ir::Input;

use super::dialect::{self, single_quoted, Dialect};
use super::plan::Plan;
use super::Program;

/// Fortran's spelling (one-based indices, double-precision literals).
pub(super) struct Fortran {
    /// Coordinates before speeds in the state.
    pub(super) n_coordinates: usize,
}

impl Dialect for Fortran {
    fn input(&self, input: Input) -> String {
        dialect::array_read(input, self.n_coordinates, 1, ("(", ")"), &self.nan())
    }
    fn number(&self, x: f64) -> String {
        double(x)
    }
    fn powi(&self, a: &str, k: i32) -> String {
        format!("{a}**({k})")
    }
    fn powf(&self, a: &str, b: &str) -> String {
        format!("{a}**{b}")
    }
    fn func(&self, f: Func, a: &str) -> String {
        match f {
            Func::Sign => format!("(merge(1d0, 0d0, {a} > 0d0) - merge(1d0, 0d0, {a} < 0d0))"),
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
        "ieee_value(1d0, ieee_quiet_nan)".into()
    }
}

/// `x` as a double-precision literal (`0.3d0`, `1d-7`).
pub(super) fn double(x: f64) -> String {
    let s = dialect::shortest(x);
    match s.split_once('e') {
        Some((mantissa, exponent)) => format!("{mantissa}d{exponent}"),
        None => format!("{s}d0"),
    }
}

/// One statement laid out from column 7, continued over lines of at most 72 columns: broken
/// after a space or comma outside a string where one is near the end of the line, else (inside
/// a string, where padding would be text) at the full width.
pub(super) fn statement(out: &mut String, text: &str) {
    const WIDTH: usize = 66;
    let chars: Vec<char> = text.chars().collect();
    let mut in_string = vec![false; chars.len() + 1];
    for (i, c) in chars.iter().enumerate() {
        in_string[i + 1] = in_string[i] != (*c == '\'');
    }
    let (mut start, mut first) = (0, true);
    while start < chars.len() {
        let lead = if first { "      " } else { "     &" };
        first = false;
        if chars.len() - start <= WIDTH {
            let line: String = chars[start..].iter().collect();
            out.push_str(format!("{lead}{line}").trim_end());
            out.push('\n');
            return;
        }
        let full = start + WIDTH;
        let end = (start + WIDTH / 2..full)
            .rev()
            .find(|&i| matches!(chars[i - 1], ' ' | ',') && !in_string[i])
            .unwrap_or(full);
        let line: String = chars[start..end].iter().collect();
        out.push_str(&format!("{:<72}&\n", format!("{lead}{line}")));
        start = end;
    }
}

/// `text` with each line that a continuation follows ended by `&` at column 73.
pub(super) fn continued(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::new();
    for (i, line) in lines.iter().enumerate() {
        if lines.get(i + 1).is_some_and(|next| next.starts_with("     &")) {
            out.push_str(&format!("{line:<72}&\n"));
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// A comment line.
pub(super) fn comment(out: &mut String, text: &str) {
    out.push_str(format!("! {text}").trim_end());
    out.push('\n');
}

/// The Fortran name of the program in the file `stem` whose statements are `body`: its letters,
/// digits and `_` (any other character as `_`), at most 63 characters, after `p_` when it does not
/// start with a letter or is a name `body` uses (Fortran names are not case-sensitive).
pub(super) fn program_name(stem: &str, body: &str) -> String {
    let mut name: String = stem.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    if !name.starts_with(|c: char| c.is_ascii_alphabetic()) || uses_name(body, &name) {
        name.insert_str(0, "p_");
    }
    name.truncate(63);
    name
}

/// Whether the Fortran `text` uses `name` outside its comments and quoted strings.
fn uses_name(text: &str, name: &str) -> bool {
    text.lines().any(|line| {
        let mut code = String::new();
        let mut quote = None;
        for c in line.chars() {
            match (quote, c) {
                (None, '!') => break,
                (None, '\'' | '"') => quote = Some(c),
                (Some(q), _) if c == q => quote = None,
                (None, _) => code.push(c),
                _ => {}
            }
        }
        code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|word| word.eq_ignore_ascii_case(name))
    })
}

/// The Fortran program of `plan`, its file named `stem`.
pub(super) fn program(plan: &Plan<'_>, stem: &str, about: &Program) -> String {
    let f = Fortran { n_coordinates: plan.info.n_coordinates };
    let mut out = String::new();
    for line in
        about.header_lines(&format!("gfortran -O2 -o {stem} {stem}.f90 && ./{stem} [OUT.csv]"), plan.once)
    {
        comment(&mut out, &line);
    }
    let mut body = String::new();
    statement(&mut body, "use, intrinsic :: ieee_arithmetic");
    statement(&mut body, "use, intrinsic :: iso_fortran_env, only: error_unit");
    statement(&mut body, "implicit none");
    let (ny, np) = (plan.info.state_names.len(), plan.params.len());
    let nk = plan.program.param_constants.results.len().max(1);
    statement(
        &mut body,
        &format!(
            "integer, parameter :: ny = {ny}, np = {np}, nk = {nk}, ncol = {}",
            plan.columns.len().max(1)
        ),
    );
    values(&mut body, plan, stem);
    body.push_str(&continued(&DRIVER.replace("STEM", stem)));
    functions(&mut body, plan, &f);
    enclose(&mut out, stem, &body);
    out
}

/// `body` as the program of the file `stem`, after `out`.
pub(super) fn enclose(out: &mut String, stem: &str, body: &str) {
    let name = program_name(stem, body);
    statement(out, &format!("program {name}"));
    out.push_str(body);
    statement(out, &format!("end program {name}"));
}

/// The items of an array constructor of `values` (-huge where not finite).
pub(super) fn reals(values: &[f64]) -> String {
    let items: Vec<String> =
        values.iter().map(|v| if v.is_finite() { double(*v) } else { "-huge(1d0)".into() }).collect();
    if items.is_empty() {
        "0d0".into()
    } else {
        items.join(", ")
    }
}

/// The length and the items of a character array constructor of `values`, padded to one length.
pub(super) fn names(values: &[&str]) -> (usize, String) {
    let width = values.iter().map(|v| v.len()).max().unwrap_or(1).max(1);
    let items: Vec<String> = values.iter().map(|v| single_quoted(&format!("{v:<width$}"))).collect();
    (width, if items.is_empty() { "' '".into() } else { items.join(", ") })
}

/// Declarations and values of the main program.
fn values(out: &mut String, plan: &Plan<'_>, stem: &str) {
    let info = plan.info;
    let s = plan.settings;
    comment(out, "The file's INPUT values (internal units: angles in radians); -huge where it gives none.");
    let p0 = if plan.params.is_empty() { vec![0.0] } else { plan.start_params() };
    statement(out, &format!("real(8), parameter :: p0(max(np, 1)) = (/ {} /)", reals(&p0)));
    statement(out, &format!("real(8), parameter :: y0(ny) = (/ {} /)", reals(&plan.initial)));
    let (w, text) = names(if info.param_names.is_empty() { &[""] } else { info.param_names });
    statement(out, &format!("character(len={w}), parameter :: p_names(max(np, 1)) = (/ {text} /)"));
    let (w, text) = names(info.state_names);
    statement(out, &format!("character(len={w}), parameter :: y_names(ny) = (/ {text} /)"));
    let open: Vec<&str> = info.open_inputs.iter().map(|i| info.param_names[*i]).collect();
    statement(
        out,
        &format!("character(len=*), parameter :: open_inputs = {}", single_quoted(&open.join(", "))),
    );
    statement(out, &format!("character(len=*), parameter :: header = {}", single_quoted(&plan.header())));
    statement(out, &format!("character(len=*), parameter :: name = '{stem}'"));
    statement(
        out,
        &format!(
            "real(8), parameter :: t_final = {}, step = {}, rtol = {}, atol = {}",
            double(s.t_final),
            double(s.output_step),
            double(s.rtol),
            double(s.atol)
        ),
    );
}

/// Declares the temporaries `lines` assign, then the statements.
pub(super) fn body(out: &mut String, lines: &[String]) {
    let names: Vec<&str> = lines.iter().filter_map(|l| l.split_once(" = ").map(|(n, _)| n)).collect();
    for group in names.chunks(40) {
        statement(out, &format!("real(8) :: {}", group.join(", ")));
    }
    lines.iter().for_each(|l| statement(out, l));
}

/// The internal procedures `constants`, `rhs` and `row`.
fn functions(out: &mut String, plan: &Plan<'_>, f: &Fortran) {
    let p = plan.program;
    comment(out, "The parameter-only quantities of p (once per parameter set).");
    statement(out, "subroutine constants(p, k)");
    statement(out, "real(8), intent(in) :: p(:)");
    statement(out, "real(8), intent(out) :: k(nk)");
    let (lines, results) = dialect::print(&p.param_constants, f, "c");
    body(out, &lines);
    statement(out, "k = 0d0");
    results.iter().enumerate().for_each(|(i, r)| statement(out, &format!("k({}) = {r}", i + 1)));
    statement(out, "end subroutine constants");
    comment(out, "dy = f(t, y): coordinates' rates, then speeds' rates; k = constants of p.");
    statement(out, "subroutine rhs(t, y, p, k, dy)");
    statement(out, "real(8), intent(in) :: t, y(ny), p(:), k(nk)");
    statement(out, "real(8), intent(out) :: dy(ny)");
    let (lines, results) = dialect::print(&p.rhs, f, "v");
    body(out, &lines);
    results.iter().enumerate().for_each(|(i, r)| statement(out, &format!("dy({}) = {r}", i + 1)));
    statement(out, "end subroutine rhs");
    comment(out, "One written row after t: each column in its unit.");
    statement(out, "subroutine row(t, y, p, k, r)");
    statement(out, "real(8), intent(in) :: t, y(ny), p(:), k(nk)");
    statement(out, "real(8), intent(out) :: r(ncol)");
    if plan.needs_rates {
        statement(out, "real(8) :: dy(ny)");
    }
    let (lines, cells) = dialect::row(plan, f);
    let names: Vec<&str> = lines.iter().filter_map(|l| l.split_once(" = ").map(|(n, _)| n)).collect();
    for group in names.chunks(40) {
        statement(out, &format!("real(8) :: {}", group.join(", ")));
    }
    if plan.needs_rates {
        statement(out, "call rhs(t, y, p, k, dy)");
    }
    lines.iter().for_each(|l| statement(out, l));
    statement(out, "r = 0d0");
    cells.iter().enumerate().for_each(|(i, c)| statement(out, &format!("r({}) = {c}", i + 1)));
    statement(out, "end subroutine row");
}

/// The main program's run and the integrator, with `STEM` for the program's name; lines in
/// the shared fixed and free layout.
const DRIVER: &str = "      real(8) :: p(max(np, 1))
      character(len=4096) :: path
      integer :: i
      p = p0
      do i = 1, np
        if (p(i) == -huge(1d0)) then
          write (error_unit, '(4a)') name, ': parameter ',
     &      trim(p_names(i)),
     &      ' has no value: give it in the INPUT and regenerate'
          stop 2
        end if
      end do
      do i = 1, ny
        if (y0(i) == -huge(1d0)) then
          write (error_unit, '(4a)') name, ': state ', trim(y_names(i)),
     &      ' has no initial value: give it in the INPUT, regenerate'
          stop 2
        end if
      end do
      if (len(open_inputs) > 0) write (error_unit, '(4a)') name,
     &  ': warning: ', open_inputs,
     &  ' (inputs the model leaves open) are 0 in this run'
      if (command_argument_count() > 0) then
        call get_command_argument(1, path)
      else
        call get_command_argument(0, path)
        i = index(path, '/', back=.true.)
        path = path(1:i) // name // '.csv'
      end if
      if (run(trim(path)) /= 0) stop 1
      contains
! Integrates from 0 to t_final, writing a row at each output time
! through a temporary file; 0 on success.
      integer function run(path)
      character(len=*), intent(in) :: path
      real(8) :: k(nk), y(ny), f(ny), t, h, target
      integer :: u, n, i, status
      run = 1
      call constants(p, k)
      y = y0
      t = 0d0
      call rhs(t, y, p, k, f)
      h = min(step, 1d-3 * max(t_final, 1d-300))
      open (newunit=u, file=path // '.partial', status='replace',
     &  action='write')
      write (u, '(a)') header
      if (write_row(u, t, y, k) /= 0) go to 9
      n = int(t_final / step * (1d0 + 1d-12))
      do i = 1, n + 1
        target = dble(i) * step
        if (i == n .and. abs(target - t_final) <= 1d-12 * t_final)
     &    target = t_final
        if (i == n + 1) then
          if (t >= t_final) exit
          target = t_final
        end if
        if (advance(t, y, f, target, h, k) /= 0) then
          write (error_unit, '(2a,es24.16)') name,
     &      ': the step size fell to nothing at t = ', t
          go to 9
        end if
        if (write_row(u, t, y, k) /= 0) go to 9
      end do
      close (u)
      call rename(path // '.partial', path, status)
      if (status == 0) run = 0
      return
9     close (u, status='delete')
      end function run
! One CSV row; nonzero if a value is not finite.
      integer function write_row(u, t, y, k)
      integer, intent(in) :: u
      real(8), intent(in) :: t, y(ny), k(nk)
      real(8) :: r(ncol)
      character(len=32) :: text
      integer :: j
      write_row = 1
      call row(t, y, p, k, r)
      write (text, '(es24.16e3)') t
      write (u, '(a)', advance='no') trim(adjustl(text))
      do j = 1, size(r)
        if (.not. ieee_is_finite(r(j))) then
          write (error_unit, '(2a,i0,a,es24.16)') name, ': column ',
     &      j + 1, ' is not finite at t = ', t
          return
        end if
        write (text, '(es24.16e3)') r(j)
        write (u, '(2a)', advance='no') ',', trim(adjustl(text))
      end do
      write (u, '(a)') ''
      write_row = 0
      end function write_row
! Integrates from t to t_end, h the step to try (updated).
      integer function advance(t, y, f, t_end, h, k)
      real(8), intent(inout) :: t, y(ny), f(ny), h
      real(8), intent(in) :: t_end, k(nk)
      real(8) :: y1(ny), f1(ny), dt, err, factor
      advance = 1
      do while (t < t_end)
        dt = min(h, t_end - t)
        if (.not. (dt > 1d-14 * max(1d0, abs(t)))) return
        err = dopri_step(t, y, f, dt, k, y1, f1)
        if (.not. ieee_is_finite(err)) err = 1d10
        factor = 5d0
        if (err > 0d0) factor = 0.9d0 * err**(-0.2d0)
        factor = min(5d0, max(0.2d0, factor))
        if (err <= 1d0) then
          if (t_end - t - dt <= 1d-14 * max(1d0, abs(t_end))) then
            t = t_end
          else
            t = t + dt
          end if
          y = y1
          f = f1
          if (dt == h .or. factor < 1d0) h = dt * factor
        else
          h = dt * min(1d0, factor)
        end if
      end do
      advance = 0
      end function advance
! Dormand-Prince 5(4): one step of size h into y1, its error norm.
      real(8) function dopri_step(t, y, f0, h, k, y1, f1)
      real(8), intent(in) :: t, y(ny), f0(ny), h, k(nk)
      real(8), intent(out) :: y1(ny), f1(ny)
      real(8) :: a(6, 6), c(6), e(7), st(ny, 7), yi(ny), sc(ny)
      integer :: s, j
      a = 0d0
      a(1, 1) = 1d0 / 5
      a(2, 1:2) = (/ 3d0 / 40, 9d0 / 40 /)
      a(3, 1:3) = (/ 44d0 / 45, -56d0 / 15, 32d0 / 9 /)
      a(4, 1:4) = (/ 19372d0 / 6561, -25360d0 / 2187, 64448d0 / 6561,
     &  -212d0 / 729 /)
      a(5, 1:5) = (/ 9017d0 / 3168, -355d0 / 33, 46732d0 / 5247,
     &  49d0 / 176, -5103d0 / 18656 /)
      a(6, 1:6) = (/ 35d0 / 384, 0d0, 500d0 / 1113, 125d0 / 192,
     &  -2187d0 / 6784, 11d0 / 84 /)
      c = (/ 1d0 / 5, 3d0 / 10, 4d0 / 5, 8d0 / 9, 1d0, 1d0 /)
      e = (/ 71d0 / 57600, 0d0, -71d0 / 16695, 71d0 / 1920,
     &  -17253d0 / 339200, 22d0 / 525, -1d0 / 40 /)
      st(:, 1) = f0
      do s = 1, 6
        yi = y
        do j = 1, s
          yi = yi + h * a(s, j) * st(:, j)
        end do
        call rhs(t + c(s) * h, yi, p, k, st(:, s + 1))
      end do
      y1 = yi
      f1 = st(:, 7)
      sc = atol + rtol * max(abs(y), abs(y1))
      dopri_step = sqrt(sum((h * matmul(st, e) / sc)**2) / ny)
      end function dopri_step
";

/// Panics unless every code line of `text` ends by column 72 and a continued one has `&` at 73.
#[cfg(test)]
pub(super) fn assert_shared_form(text: &str) {
    for line in text.lines().filter(|l| !l.starts_with('!')) {
        let code = line.strip_suffix('&').unwrap_or(line).trim_end();
        assert!(code.len() <= 72, "{line}");
        assert!(!line.ends_with('&') || line.len() == 73, "`&` at column 73: {line}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_driver_keeps_to_72_columns() {
        assert_shared_form(&continued(DRIVER));
    }

    #[test]
    fn a_file_stem_that_is_no_fortran_name_gives_the_program_one() {
        let body = "call rhs(t, y) ! phase3\nopen(newunit=u, file='phase3.csv')\n";
        assert_eq!(program_name("phase3", body), "phase3");
        assert_eq!(program_name("7segSprint_raw", body), "p_7segSprint_raw");
        assert_eq!(program_name("model-ad.v2", body), "model_ad_v2");
        assert_eq!(program_name("RHS", body), "p_RHS", "a name the program uses");
        assert_eq!(program_name(&"x".repeat(80), body).len(), 63);
    }

    #[test]
    fn a_name_with_a_quote_is_written_with_the_quote_doubled() {
        // A SPECIFIED quantity's rates are named with primes: px' and px''.
        assert_eq!(names(&["px", "px'", "px''"]), (4, "'px  ', 'px'' ', 'px'''''".into()));
    }

    #[test]
    fn long_statements_are_continued_inside_strings_too() {
        let mut out = String::new();
        let text = format!("character(len=*), parameter :: header = '{}'", "q1_deg,".repeat(30));
        statement(&mut out, &text);
        let lines: Vec<&str> = out.lines().collect();
        assert!(lines.len() > 2);
        assert!(lines[..lines.len() - 1].iter().all(|l| l.len() == 73 && l.ends_with('&')));
        assert!(lines[1..].iter().all(|l| l.starts_with("     &")));
        let joined: String =
            lines.iter().map(|l| l.trim_end_matches('&').trim_start_matches("     &")).collect();
        let squeeze = |s: &str| s.replace(' ', "");
        assert_eq!(squeeze(&joined), squeeze(&text));
        let literal = format!("'{}'", "q1_deg,".repeat(30));
        assert!(joined.contains(&literal), "the string is continued without padding: {joined}");
    }
}
