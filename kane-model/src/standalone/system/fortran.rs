//! A CODE ALGEBRAIC or NONLINEAR system as a Fortran program: the residuals and Jacobian as an
//! internal subroutine, Gaussian elimination with partial pivoting and the Newton iteration of
//! `kane solve`, the solution printed and written as CSV; laid out as the dynamics program is,
//! so one text compiles as `.f`, `.for` and `.f90`.

use crate::program::ir::Input;

use super::super::dialect::single_quoted;
use super::super::fortran::{body, comment, continued, double, enclose, names, reals, statement, Fortran};
use super::{Program, SystemPlan, SINGULAR_PIVOT, TOLERANCE};

/// The Fortran program of `plan`, its file named `stem`.
pub(super) fn program(plan: &SystemPlan, stem: &str, about: &Program) -> String {
    let mut out = String::new();
    let build = format!("gfortran -O2 -o {stem} {stem}.f90 && ./{stem} [OUT.csv]");
    for line in about.system_header_lines(plan, &build) {
        comment(&mut out, &line);
    }
    let mut body = String::new();
    statement(&mut body, "use, intrinsic :: ieee_arithmetic");
    statement(&mut body, "use, intrinsic :: iso_fortran_env, only: error_unit");
    statement(&mut body, "implicit none");
    let (n, nv) = (plan.unknowns.len(), plan.names.len());
    statement(&mut body, &format!("integer, parameter :: nx = {n}, nv = {nv}, np = {}", nv.max(1)));
    comment(
        &mut body,
        "The file's INPUT values (internal units: angles in radians); -huge where it gives none.",
    );
    statement(&mut body, &format!("real(8), parameter :: p0(np) = (/ {} /)", reals(&plan.values)));
    let (w, text) = names(&as_str(&plan.names));
    statement(&mut body, &format!("character(len={w}), parameter :: p_names(np) = (/ {text} /)"));
    let (w, text) = names(&as_str(&plan.unknowns));
    statement(&mut body, &format!("character(len={w}), parameter :: x_names(nx) = (/ {text} /)"));
    statement(
        &mut body,
        &format!("character(len=*), parameter :: header = {}", single_quoted(&plan.header())),
    );
    statement(&mut body, &format!("character(len=*), parameter :: name = '{stem}'"));
    if plan.evaluation {
        let driver = [DECLARE, CHECK_PARAMETERS, EVALUATE, WRITE].concat();
        body.push_str(&continued(&driver.replace("STEM", stem)));
        values(&mut body, plan);
    } else {
        newton_settings(&mut body, plan);
        let driver = [DECLARE, DECLARE_NEWTON, CHECK_PARAMETERS, NEWTON, WRITE, NEWTON_HELPERS].concat();
        body.push_str(&continued(&driver.replace("STEM", stem)));
        equations(&mut body, plan);
    }
    enclose(&mut out, stem, &body);
    out
}

/// The starting values and the iteration's settings.
fn newton_settings(body: &mut String, plan: &SystemPlan) {
    statement(body, &format!("real(8), parameter :: x0(nx) = (/ {} /)", reals(&plan.start)));
    statement(body, &format!("integer, parameter :: steps = {}", plan.steps()));
    let logical = |b: bool| if b { ".true." } else { ".false." };
    statement(
        body,
        &format!(
            "logical, parameter :: damped = {}, check_start = {}",
            logical(plan.damped()),
            logical(plan.checked_start())
        ),
    );
    statement(
        body,
        &format!(
            "real(8), parameter :: tolerance = {}, singular = {}",
            double(TOLERANCE),
            double(SINGULAR_PIVOT)
        ),
    );
}

/// `v` as string slices, one empty name where there is none (Fortran has no empty array
/// constructor of characters).
fn as_str(v: &[String]) -> Vec<&str> {
    if v.is_empty() {
        vec![""]
    } else {
        v.iter().map(String::as_str).collect()
    }
}

/// The internal subroutine `equations`.
fn equations(out: &mut String, plan: &SystemPlan) {
    let n = plan.unknowns.len();
    comment(out, "The residuals r and the Jacobian jac (row by row) at the unknowns y.");
    let declared = ["real(8), intent(in) :: y(nx), p(np)", "real(8), intent(out) :: r(nx), jac(nx * nx)"];
    subroutine(out, plan, "equations(y, p, r, jac)", &declared, |i| {
        if i < n {
            format!("r({})", i + 1)
        } else {
            format!("jac({})", i - n + 1)
        }
    });
}

/// The internal subroutine `values`.
fn values(out: &mut String, plan: &SystemPlan) {
    comment(out, "The quantities x at the parameters p.");
    let declared = ["real(8), intent(in) :: p(np)", "real(8), intent(out) :: x(nx)"];
    subroutine(out, plan, "values(p, x)", &declared, |i| format!("x({})", i + 1));
}

/// The subroutine `call` (its name and arguments) declaring `declared`, computing `plan`'s
/// section and storing result `i` in `into(i)`.
fn subroutine(
    out: &mut String,
    plan: &SystemPlan,
    call: &str,
    declared: &[&str],
    into: impl Fn(usize) -> String,
) {
    let name = call.split('(').next().unwrap_or(call);
    statement(out, &format!("subroutine {call}"));
    declared.iter().for_each(|d| statement(out, d));
    if plan.section.inputs.contains(&Input::Time) {
        statement(out, "real(8), parameter :: t = 0d0");
    }
    let (lines, results) = super::super::dialect::print(&plan.section, &Fortran { n_coordinates: 0 }, "v");
    body(out, &lines);
    for (i, v) in results.iter().enumerate() {
        statement(out, &format!("{} = {v}", into(i)));
    }
    statement(out, &format!("end subroutine {name}"));
}

/// The declarations every program has; lines in the shared fixed and free layout (as below).
const DECLARE: &str = "      real(8) :: x(nx)
      character(len=4096) :: path
      character(len=32) :: text
      integer :: i, u, status
";

/// The iteration's declarations.
const DECLARE_NEWTON: &str = "      real(8) :: r(nx), jac(nx * nx), trial(nx), rt(nx)
      real(8) :: jt(nx * nx), dx(nx), scale, step
      integer :: iteration
      logical :: converged
";

/// Every parameter's value checked, with `STEM` for the program's name.
const CHECK_PARAMETERS: &str = "      do i = 1, nv
        if (p0(i) == -huge(1d0)) then
          write (error_unit, '(4a)') name, ': ', trim(p_names(i)),
     &      ' has no value: give it in the INPUT and regenerate'
          stop 2
        end if
      end do
";

/// The iteration from the file's starting values.
const NEWTON: &str = "      do i = 1, nx
        if (check_start .and. x0(i) == -huge(1d0)) then
          write (error_unit, '(4a)') name, ': ', trim(x_names(i)),
     &      ' has no starting value: give it in the INPUT, regenerate'
          stop 2
        end if
      end do
      x = x0
      call equations(x, p0, r, jac)
      scale = 1d0 + largest(jac) * max(largest(x), 1d0)
      converged = .false.
      do iteration = 0, steps - 1
        if (.not. ieee_is_finite(largest(r)))
     &    call fail('the equations are not finite at ', x)
        if (largest(r) <= tolerance * scale .and. iteration > 0) then
          converged = .true.
          exit
        end if
        dx = -r
        if (eliminate(jac, dx) /= 0)
     &    call fail('the Jacobian of the equations is singular at ', x)
        step = 1d0
        do
          trial = x + step * dx
          call equations(trial, p0, rt, jt)
          if (largest(rt) < largest(r) .or. step < 1d-4 .or.
     &      .not. damped) exit
          step = step / 2
        end do
        x = trial
        r = rt
        jac = jt
      end do
      if (.not. converged .and. damped .and.
     &  .not. largest(r) <= tolerance * scale)
     &  call fail('Newton''s method did not converge at ', x)
";

/// An evaluation: the quantities at the parameters, each finite.
const EVALUATE: &str = "      call values(p0, x)
      do i = 1, nx
        if (.not. ieee_is_finite(x(i))) then
          write (text, '(es24.16e3)') x(i)
          write (error_unit, '(5a)') name, ': ', trim(x_names(i)),
     &      ' is not finite at the INPUT values: ', trim(adjustl(text))
          stop 1
        end if
      end do
";

/// The solution printed and written as CSV, then `contains`.
const WRITE: &str = "      if (command_argument_count() > 0) then
        call get_command_argument(1, path)
      else
        call get_command_argument(0, path)
        i = index(path, '/', back=.true.)
        path = path(1:i) // name // '.csv'
      end if
      open (newunit=u, file=trim(path) // '.partial', status='replace',
     &  action='write')
      write (u, '(a)') header
      do i = 1, nx
        write (text, '(es24.16e3)') x(i)
        write (*, '(3a)') trim(x_names(i)), ' = ', trim(adjustl(text))
        if (i > 1) write (u, '(a)', advance='no') ','
        write (u, '(a)', advance='no') trim(adjustl(text))
      end do
      write (u, '(a)') ''
      close (u)
      call rename(trim(path) // '.partial', trim(path), status)
      if (status /= 0) stop 1
      contains
";

/// The iteration's functions: `largest`, `fail` and the elimination.
const NEWTON_HELPERS: &str = "! The largest magnitude in v, NaN if one is not a number.
      real(8) function largest(v)
      real(8), intent(in) :: v(:)
      if (any(ieee_is_nan(v))) then
        largest = ieee_value(1d0, ieee_quiet_nan)
      else
        largest = max(0d0, maxval(abs(v)))
      end if
      end function largest
! Says what failed and where, and stops.
      subroutine fail(what, x)
      character(len=*), intent(in) :: what
      real(8), intent(in) :: x(nx)
      integer :: i
      write (error_unit, '(3a)', advance='no') name, ': ', what
      do i = 1, nx
        write (text, '(es24.16e3)') x(i)
        if (i > 1) write (error_unit, '(a)', advance='no') ', '
        write (error_unit, '(3a)', advance='no') trim(x_names(i)),
     &    ' = ', trim(adjustl(text))
      end do
      write (error_unit, '(a)') ''
      stop 1
      end subroutine fail
! Solves a x = b in place of b (a row by row) by partial pivoting;
! 1 if singular.
      integer function eliminate(a0, b)
      real(8), intent(in) :: a0(nx * nx)
      real(8), intent(inout) :: b(nx)
      real(8) :: a(nx * nx), big, f, s
      integer :: c, row, j, pivot
      a = a0
      eliminate = 1
      big = largest(a)
      do c = 1, nx
        pivot = c
        do row = c + 1, nx
          if (abs(a((row - 1) * nx + c)) > abs(a((pivot - 1) * nx + c)))
     &      pivot = row
        end do
        if (.not. abs(a((pivot - 1) * nx + c)) > singular * big) return
        do j = 1, nx
          s = a((c - 1) * nx + j)
          a((c - 1) * nx + j) = a((pivot - 1) * nx + j)
          a((pivot - 1) * nx + j) = s
        end do
        s = b(c)
        b(c) = b(pivot)
        b(pivot) = s
        do row = c + 1, nx
          f = a((row - 1) * nx + c) / a((c - 1) * nx + c)
          do j = c, nx
            a((row - 1) * nx + j) = a((row - 1) * nx + j)
     &        - f * a((c - 1) * nx + j)
          end do
          b(row) = b(row) - f * b(c)
        end do
      end do
      do c = nx, 1, -1
        s = b(c)
        do j = c + 1, nx
          s = s - a((c - 1) * nx + j) * b(j)
        end do
        b(c) = s / a((c - 1) * nx + c)
      end do
      eliminate = 0
      end function eliminate
";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_driver_keeps_to_72_columns() {
        for text in [DECLARE, DECLARE_NEWTON, CHECK_PARAMETERS, NEWTON, EVALUATE, WRITE, NEWTON_HELPERS] {
            super::super::super::fortran::assert_shared_form(&continued(text));
        }
    }
}
