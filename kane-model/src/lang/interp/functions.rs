//! Autolev functions that return values: elementary functions, vector algebra, derivatives,
//! substitution, matrices, and mass properties.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, Func};
use crate::mechanics::Vector;

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{At, Binding, IResult, Interpreter};

/// Functions known to Autolev that this implementation rejects, with the reason.
const UNSUPPORTED: &[(&str, &str)] = &[
    ("TAYLOR", "series expansion"),
    ("POLYNOMIAL", "polynomial construction"),
    ("ROOTS", "polynomial roots"),
    ("EIG", "eigenvalues (use Model::linearize and a numeric eigen-solver)"),
    ("FACTORIAL", "factorial"),
    ("CEIL", "ceiling"),
    ("FLOOR", "floor"),
    ("INT", "integer part"),
    ("ROUND", "rounding"),
    ("INCLUDE", "term selection"),
    ("EXCLUDE", "term selection"),
    ("INV", "symbolic matrix inverse"),
    ("NICHECK", "Newtonian-inertia check"),
];

impl Interpreter {
    /// Evaluates `NAME(args)`.
    pub(crate) fn call(&mut self, name: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let upper = name.to_ascii_uppercase();
        let fail: &Span = &e.span;
        let arity = |n: usize| super::arity(&upper, args, n, &e.span);
        if let Some(f) = elementary(&upper) {
            arity(1)?;
            let x = self.scalar(&args[0])?;
            return Ok(Value::Scalar(match f {
                Elementary::Func(f) => self.model.ar.func(f, x).at(fail)?,
                Elementary::Sqrt => self.model.ar.sqrt(x).at(fail)?,
                Elementary::Square => self.model.ar.powi(x, 2).at(fail)?,
                Elementary::Log10 => {
                    let ln = self.model.ar.func(Func::Ln, x).at(fail)?;
                    let ln10 = self.model.ar.float(std::f64::consts::LN_10).at(fail)?;
                    self.model.ar.div(ln, ln10).at(fail)?
                }
            }));
        }
        match upper.as_str() {
            "DOT" => {
                arity(2)?;
                let a = self.vector(&args[0])?;
                let b = self.vector(&args[1])?;
                Ok(Value::Scalar(self.model.dot(&a, &b).at(fail)?))
            }
            "CROSS" => {
                arity(2)?;
                let a = self.vector(&args[0])?;
                let b = self.vector(&args[1])?;
                Ok(Value::Vector(self.model.cross(&a, &b).at(fail)?))
            }
            "MAG" => {
                arity(1)?;
                let v = self.vector(&args[0])?;
                Ok(Value::Scalar(self.model.magnitude(&v).at(fail)?))
            }
            "UNITVEC" => {
                arity(1)?;
                let v = self.vector(&args[0])?;
                let m = self.model.magnitude(&v).at(fail)?;
                let one = self.model.ar.one();
                let inv = self.model.ar.div(one, m).at(fail)?;
                Ok(Value::Vector(self.model.scale(&v, inv).at(fail)?))
            }
            "EXPRESS" => {
                arity(2)?;
                let v = self.eval(&args[0])?;
                let f = self.frame_arg(&args[1])?;
                Ok(match v {
                    Value::Vector(v) => Value::Vector(self.model.express_vector(&v, f).at(fail)?),
                    other => other,
                })
            }
            "DT" => match args.len() {
                1 => {
                    let v = self.eval(&args[0])?;
                    self.map_scalars(&v, &e.span, |m, x| m.dt(x))
                }
                2 => {
                    let v = self.vector(&args[0])?;
                    let f = self.frame_arg(&args[1])?;
                    Ok(Value::Vector(self.model.dt_in(&v, f).at(fail)?))
                }
                _ => Err(Diagnostic::error(e.span.clone(), "DT takes (x) or (v>, frame)")),
            },
            "D" => {
                if args.len() < 2 {
                    return Err(Diagnostic::error(e.span.clone(), "D takes (x, y) or (v>, y, frame)"));
                }
                let y = self.scalar(&args[1])?;
                let s = self.model.ar.as_symbol(y).ok_or_else(|| {
                    Diagnostic::error(args[1].span.clone(), "D differentiates with respect to a symbol")
                })?;
                let v = self.eval(&args[0])?;
                if let (3, Value::Vector(vec)) = (args.len(), &v) {
                    // A term is re-expressed in the frame only where its orientation there
                    // depends on the variable; otherwise its measure numbers are differentiated.
                    let f = self.frame_arg(&args[2])?;
                    let mut out = crate::mechanics::Vector::zero();
                    for (g, m) in vec.terms() {
                        let term = Vector::new(*g, *m);
                        let c = self.model.dcm(f, *g).at(fail)?;
                        let depends = self
                            .model
                            .ar
                            .free_symbols(&c.iter().flatten().copied().collect::<Vec<_>>())
                            .contains(&s);
                        let term = if depends { self.model.express_vector(&term, f).at(fail)? } else { term };
                        let d = self.model.partial(&term, s).at(fail)?;
                        out = self.model.add_vectors(&out, &d).at(fail)?;
                    }
                    return Ok(Value::Vector(out));
                }
                self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.diff(x, s)?))
            }
            "PARTIALS" => {
                arity(2)?;
                let v = self.vector(&args[0])?;
                let u = self.scalar(&args[1])?;
                let s = self
                    .model
                    .ar
                    .as_symbol(u)
                    .ok_or_else(|| Diagnostic::error(args[1].span.clone(), "PARTIALS takes a speed"))?;
                Ok(Value::Vector(self.model.partial(&v, s).at(fail)?))
            }
            "EVALUATE" | "REPLACE" => {
                let v = self.eval(args.first().ok_or_else(|| {
                    Diagnostic::error(e.span.clone(), format!("{upper} needs an expression"))
                })?)?;
                let mut map = FxHashMap::default();
                for a in &args[1..] {
                    let ExprKind::NamedArg(n, value) = &a.kind else {
                        return Err(Diagnostic::error(
                            a.span.clone(),
                            format!("{upper} takes substitutions NAME = value"),
                        ));
                    };
                    let key = self.scalar(&Expr {
                        kind: ExprKind::Name { name: n.clone(), primes: 0, suffix: 0 },
                        span: a.span.clone(),
                    })?;
                    let val = self.scalar(value)?;
                    map.insert(key, val);
                }
                self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.subs(x, &map)?))
            }
            "EXPLICIT" | "FACTOR" | "ARRANGE" => {
                let v = self.eval(args.first().ok_or_else(|| {
                    Diagnostic::error(e.span.clone(), format!("{upper} needs an argument"))
                })?)?;
                Ok(v)
            }
            "EXPAND" => {
                let v = self.eval(
                    args.first()
                        .ok_or_else(|| Diagnostic::error(e.span.clone(), "EXPAND needs an argument"))?,
                )?;
                self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.expand(x)?))
            }
            "COEF" => {
                arity(2)?;
                let v = self.eval(&args[0])?;
                let wrt = match self.eval(&args[1])? {
                    Value::Scalar(x) => vec![x],
                    Value::Matrix { data, .. } => data,
                    other => {
                        return Err(Diagnostic::error(
                            args[1].span.clone(),
                            format!("COEF takes symbols, not {}", other.kind()),
                        ))
                    }
                };
                let syms = wrt
                    .iter()
                    .map(|x| {
                        self.model
                            .ar
                            .as_symbol(*x)
                            .ok_or_else(|| Diagnostic::error(args[1].span.clone(), "COEF takes symbols"))
                    })
                    .collect::<IResult<Vec<_>>>()?;
                let exprs = match v {
                    Value::Scalar(x) => vec![x],
                    Value::Matrix { data, .. } => data,
                    other => {
                        return Err(Diagnostic::error(
                            args[0].span.clone(),
                            format!("COEF takes scalars, not {}", other.kind()),
                        ))
                    }
                };
                let mut out = Vec::new();
                for x in &exprs {
                    let (c, _) = self.model.ar.linear_coefficients(*x, &syms).at(fail)?;
                    out.extend(c);
                }
                Ok(if out.len() == 1 {
                    Value::Scalar(out[0])
                } else {
                    Value::Matrix { rows: exprs.len(), cols: syms.len(), data: out }
                })
            }
            "RHS" => {
                arity(1)?;
                let ExprKind::Name { name, primes, .. } = &args[0].kind else {
                    return Err(Diagnostic::error(
                        args[0].span.clone(),
                        "RHS takes the name of a solved unknown",
                    ));
                };
                let key = format!("{}{}", name.to_ascii_uppercase(), "'".repeat(*primes as usize));
                self.solved.get(&key).map(|x| Value::Scalar(*x)).ok_or_else(|| {
                    Diagnostic::error(args[0].span.clone(), format!("`{name}` has not been solved for"))
                        .with_help("call SOLVE(EQN, ...) first")
                })
            }
            "FR" | "FRSTAR" => {
                self.prepare(&e.span)?;
                let v = if upper == "FR" {
                    self.model.generalized_active_forces()
                } else {
                    self.model.generalized_inertia_forces()
                }
                .at(fail)?;
                Ok(Value::column(v))
            }
            "KE" => {
                self.prepare(&e.span)?;
                Ok(Value::Scalar(self.model.kinetic_energy().at(fail)?))
            }
            "MOMENTUM" => {
                // MOMENTUM(LINEAR) or MOMENTUM(ANGULAR, O), in the Newtonian frame.
                self.prepare(&e.span)?;
                let which = match args.first().map(|a| &a.kind) {
                    Some(ExprKind::Name { name, .. }) => name.to_ascii_uppercase(),
                    _ => String::new(),
                };
                let n = self.model.newtonian();
                match which.as_str() {
                    "ANGULAR" if args.len() == 2 => {
                        let o = self.point_arg(&args[1])?;
                        Ok(Value::Vector(self.model.angular_momentum(o, n).at(fail)?))
                    }
                    "LINEAR" if args.len() == 1 => {
                        let masses = self.mass_list(&[], &e.span)?;
                        let mut p = Vector::zero();
                        for (m, pt) in masses {
                            let v = self.model.velocity(pt, n).at(fail)?;
                            let mv = self.model.scale(&v, m).at(fail)?;
                            p = self.model.add_vectors(&p, &mv).at(fail)?;
                        }
                        Ok(Value::Vector(p))
                    }
                    _ => {
                        Err(Diagnostic::error(e.span.clone(), "MOMENTUM takes (LINEAR) or (ANGULAR, point)"))
                    }
                }
            }
            "MASS" => {
                let masses = self.mass_list(args, &e.span)?;
                let ms: Vec<ExprId> = masses.iter().map(|(m, _)| *m).collect();
                Ok(Value::Scalar(self.model.ar.add(&ms).at(fail)?))
            }
            "CM" => {
                let origin = self.point_arg(
                    args.first().ok_or_else(|| Diagnostic::error(e.span.clone(), "CM needs a point"))?,
                )?;
                let masses = self.mass_list(&args[1..], &e.span)?;
                let mut moment = Vector::zero();
                let mut total = Vec::new();
                for (m, p) in masses {
                    let r = self.model.position(p, origin).at(fail)?;
                    let mr = self.model.scale(&r, m).at(fail)?;
                    moment = self.model.add_vectors(&moment, &mr).at(fail)?;
                    total.push(m);
                }
                let tm = self.model.ar.add(&total).at(fail)?;
                let one = self.model.ar.one();
                let inv = self.model.ar.div(one, tm).at(fail)?;
                Ok(Value::Vector(self.model.scale(&moment, inv).at(fail)?))
            }
            "INERTIA" => {
                let origin = self.point_arg(
                    args.first().ok_or_else(|| Diagnostic::error(e.span.clone(), "INERTIA needs a point"))?,
                )?;
                let names: Vec<String> = if args.len() > 1 {
                    args[1..]
                        .iter()
                        .map(|a| match &a.kind {
                            ExprKind::Name { name, .. } => Ok(name.to_ascii_uppercase()),
                            _ => Err(Diagnostic::error(a.span.clone(), "expected a body or particle name")),
                        })
                        .collect::<IResult<_>>()?
                } else {
                    let mut v: Vec<String> = self
                        .bindings
                        .iter()
                        .filter(|(_, b)| matches!(b, Binding::Body(_) | Binding::Particle(_)))
                        .map(|(k, _)| k.trim_start_matches('#').to_string())
                        .collect();
                    v.sort();
                    v
                };
                let origin_name = self.model.point_name(origin).to_string();
                let mut total = crate::mechanics::Dyadic::zero();
                for n in names {
                    let key = format!("I_{n}_{origin_name}");
                    let b = self.builtin(&key, 2).ok_or_else(|| {
                        Diagnostic::error(e.span.clone(), format!("`{n}` is not a body or particle"))
                    })?;
                    let Value::Dyadic(d) = self.builtin_value(b, &e.span)? else { continue };
                    total = self.model.add_dyadics(&total, &d).at(fail)?;
                }
                Ok(Value::Dyadic(total))
            }
            "TRANSPOSE" | "TRACE" | "DET" | "ELEMENT" | "DIAGMAT" | "ROWS" | "COLS" | "MATRIX" | "VECTOR" => {
                self.matrix_function(&upper, args, e)
            }
            _ => {
                if let Some((_, what)) = UNSUPPORTED.iter().find(|(n, _)| *n == upper) {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        format!("{upper}() ({what}) is not supported"),
                    )
                    .with_help("remove it or compute it outside the model file"));
                }
                Err(Diagnostic::error(e.span.clone(), format!("unknown function `{name}`"))
                    .with_help("see the README for the supported Autolev functions and commands"))
            }
        }
    }

    /// Applies `f` to every scalar inside a value.
    pub(crate) fn map_scalars(
        &mut self,
        v: &Value,
        span: &super::super::token::Span,
        f: impl Fn(&mut crate::mechanics::Model, ExprId) -> crate::mechanics::Result<ExprId>,
    ) -> IResult<Value> {
        let fail: &Span = span;
        Ok(match v {
            Value::Scalar(x) => Value::Scalar(f(&mut self.model, *x).at(fail)?),
            Value::Matrix { rows, cols, data } => Value::Matrix {
                rows: *rows,
                cols: *cols,
                data: data.iter().map(|x| f(&mut self.model, *x)).collect::<Result<_, _>>().at(fail)?,
            },
            Value::Vector(vec) => {
                let mut out = vec.clone();
                for (_, m) in out.terms.iter_mut() {
                    for x in m.iter_mut() {
                        *x = f(&mut self.model, *x).at(fail)?;
                    }
                }
                Value::Vector(out)
            }
            Value::Dyadic(d) => Value::Dyadic(d.clone()),
        })
    }

    pub(crate) fn frame_arg(&mut self, e: &Expr) -> IResult<crate::mechanics::FrameId> {
        if let ExprKind::Name { name, suffix: 0, primes: 0 } = &e.kind {
            if let Some(f) = self.frame_of(&name.to_ascii_uppercase()) {
                return Ok(f);
            }
        }
        Err(Diagnostic::error(e.span.clone(), "expected a frame name here")
            .with_help("frames are declared with NEWTONIAN, FRAMES or BODIES"))
    }

    pub(crate) fn point_arg(&mut self, e: &Expr) -> IResult<crate::mechanics::PointId> {
        if let ExprKind::Name { name, suffix: 0, primes: 0 } = &e.kind {
            if let Some(p) = self.point_of(&name.to_ascii_uppercase()) {
                return Ok(p);
            }
        }
        Err(Diagnostic::error(e.span.clone(), "expected a point name here")
            .with_help("points are declared with POINTS or PARTICLES; a body B has mass centre BO"))
    }

    /// Masses and mass centres of the named bodies and particles, or of all when none are named.
    fn mass_list(
        &mut self,
        args: &[Expr],
        span: &super::super::token::Span,
    ) -> IResult<Vec<(ExprId, crate::mechanics::PointId)>> {
        let mut out = Vec::new();
        let push = |s: &Self, key: &str, span: &super::super::token::Span, out: &mut Vec<_>| -> IResult<()> {
            match s.bindings.get(&super::entity_key(key)) {
                Some(Binding::Body(b)) => {
                    let body = s.model.body(*b);
                    let m = body.mass.ok_or_else(|| {
                        Diagnostic::error(span.clone(), format!("{} has no mass", body.name))
                    })?;
                    out.push((m, body.mass_center));
                }
                Some(Binding::Particle(p)) => {
                    let part = s.model.particle(*p);
                    let m = part.mass.ok_or_else(|| {
                        Diagnostic::error(span.clone(), format!("{} has no mass", part.name))
                    })?;
                    out.push((m, part.point));
                }
                _ => {
                    return Err(Diagnostic::error(span.clone(), format!("`{key}` is not a body or particle")))
                }
            }
            Ok(())
        };
        if args.is_empty() {
            let mut names: Vec<String> = self
                .bindings
                .iter()
                .filter(|(_, b)| matches!(b, Binding::Body(_) | Binding::Particle(_)))
                .map(|(k, _)| k.trim_start_matches('#').to_string())
                .collect();
            names.sort();
            for k in names {
                push(self, &k, span, &mut out)?;
            }
        }
        for a in args {
            let ExprKind::Name { name, .. } = &a.kind else {
                return Err(Diagnostic::error(a.span.clone(), "expected a body or particle name"));
            };
            push(self, &name.to_ascii_uppercase(), &a.span, &mut out)?;
        }
        Ok(out)
    }

    fn matrix_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let (least, most) = match upper {
            "TRANSPOSE" | "TRACE" | "DET" => (1, 1),
            "ELEMENT" => (3, 3),
            "DIAGMAT" => (2, 3),
            "MATRIX" | "VECTOR" => (2, 2),
            _ => (1, usize::MAX),
        };
        if args.len() < least || args.len() > most {
            return Err(Diagnostic::error(
                e.span.clone(),
                format!(
                    "{upper} takes {least}{} arguments, got {}",
                    if most == least {
                        String::new()
                    } else if most == usize::MAX {
                        " or more".into()
                    } else {
                        format!(" to {most}")
                    },
                    args.len()
                ),
            ));
        }
        let fail: &Span = &e.span;
        let matrix = |s: &mut Self, a: &Expr| -> IResult<(usize, usize, Vec<ExprId>)> {
            match s.eval(a)? {
                Value::Matrix { rows, cols, data } => Ok((rows, cols, data)),
                Value::Scalar(x) => Ok((1, 1, vec![x])),
                other => Err(Diagnostic::error(
                    a.span.clone(),
                    format!("expected a matrix, found {}", other.kind()),
                )),
            }
        };
        match upper {
            "TRANSPOSE" => {
                let (r, c, d) = matrix(self, &args[0])?;
                let data =
                    (0..c).flat_map(|j| (0..r).map(move |i| (i, j))).map(|(i, j)| d[i * c + j]).collect();
                Ok(Value::Matrix { rows: c, cols: r, data })
            }
            "TRACE" => {
                let (r, c, d) = matrix(self, &args[0])?;
                let diag: Vec<ExprId> = (0..r.min(c)).map(|i| d[i * c + i]).collect();
                Ok(Value::Scalar(self.model.ar.add(&diag).at(fail)?))
            }
            "DET" => {
                let (r, c, d) = matrix(self, &args[0])?;
                if r != c || r > 4 {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        "DET needs a square matrix of size 4 or less",
                    ));
                }
                Ok(Value::Scalar(determinant(&mut self.model.ar, &d, r).at(fail)?))
            }
            "ELEMENT" => {
                let (r, c, d) = matrix(self, &args[0])?;
                let i = self.index_value(&args[1])?;
                let j = self.index_value(&args[2])?;
                super::value::matrix_position(&[i, j], r, c).map(|k| Value::Scalar(d[k])).ok_or_else(|| {
                    Diagnostic::error(
                        e.span.clone(),
                        format!("ELEMENT({i}, {j}) is outside the {r}x{c} matrix"),
                    )
                })
            }
            "DIAGMAT" => {
                let (n, m, x) = match args.len() {
                    2 => (self.index_value(&args[0])? as usize, None, self.scalar(&args[1])?),
                    3 => (
                        self.index_value(&args[0])? as usize,
                        Some(self.index_value(&args[1])? as usize),
                        self.scalar(&args[2])?,
                    ),
                    _ => {
                        return Err(Diagnostic::error(
                            e.span.clone(),
                            "DIAGMAT takes (n, x) or (rows, cols, x)",
                        ))
                    }
                };
                let cols = m.unwrap_or(n);
                if !(1..=1000).contains(&n) || !(1..=1000).contains(&cols) {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        "DIAGMAT sizes must be between 1 and 1000",
                    ));
                }
                let z = self.model.ar.zero();
                let data = (0..n * cols).map(|k| if k / cols == k % cols { x } else { z }).collect();
                Ok(Value::Matrix { rows: n, cols, data })
            }
            "ROWS" | "COLS" => {
                let (r, c, d) = matrix(self, &args[0])?;
                if args.len() == 1 {
                    let n = if upper == "ROWS" { r } else { c };
                    return Ok(Value::Scalar(self.model.ar.integer(n as i128)));
                }
                let mut picks = Vec::new();
                for a in &args[1..] {
                    match &a.kind {
                        ExprKind::Range(lo, hi) => {
                            let (lo, hi) = (self.index_value(lo)?, self.index_value(hi)?);
                            let limit = if upper == "ROWS" { r } else { c } as i64;
                            if lo < 1 || hi > limit || lo > hi {
                                return Err(Diagnostic::error(
                                    a.span.clone(),
                                    format!("{upper} range {lo}:{hi} is outside 1..{limit}"),
                                ));
                            }
                            picks.extend(lo..=hi);
                        }
                        _ => picks.push(self.index_value(a)?),
                    }
                }
                let limit = if upper == "ROWS" { r } else { c };
                if picks.iter().any(|p| *p < 1 || *p as usize > limit) {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        format!("{upper} index out of range 1..{limit}"),
                    ));
                }
                let mut data = Vec::new();
                if upper == "ROWS" {
                    for p in &picks {
                        data.extend_from_slice(&d[(*p as usize - 1) * c..*p as usize * c]);
                    }
                    Ok(Value::Matrix { rows: picks.len(), cols: c, data })
                } else {
                    for i in 0..r {
                        for p in &picks {
                            data.push(d[i * c + *p as usize - 1]);
                        }
                    }
                    Ok(Value::Matrix { rows: r, cols: picks.len(), data })
                }
            }
            "MATRIX" => {
                let f = self.frame_arg(&args[0])?;
                let Value::Dyadic(dy) = self.eval(&args[1])? else {
                    return Err(Diagnostic::error(args[1].span.clone(), "MATRIX takes a frame and a dyadic"));
                };
                let mut data = Vec::with_capacity(9);
                for i in 1..=3 {
                    for j in 1..=3 {
                        let ui = self.model.unit(f, i);
                        let uj = self.model.unit(f, j);
                        let dj = self.model.dyadic_dot(&dy, &uj).at(fail)?;
                        data.push(self.model.dot(&ui, &dj).at(fail)?);
                    }
                }
                Ok(Value::Matrix { rows: 3, cols: 3, data })
            }
            _ => {
                // VECTOR(frame, column)
                let f = self.frame_arg(&args[0])?;
                let (_, _, d) = matrix(self, &args[1])?;
                if d.len() != 3 {
                    return Err(Diagnostic::error(
                        args[1].span.clone(),
                        "VECTOR needs three measure numbers",
                    ));
                }
                Ok(Value::Vector(Vector::new(f, [d[0], d[1], d[2]])))
            }
        }
    }
}

enum Elementary {
    Func(Func),
    Sqrt,
    Square,
    Log10,
}

fn elementary(name: &str) -> Option<Elementary> {
    Some(match name {
        "LOG" | "LN" => Elementary::Func(Func::Ln),
        "SQRT" => Elementary::Sqrt,
        "SQR" => Elementary::Square,
        "LOG10" => Elementary::Log10,
        _ => Elementary::Func(Func::from_name(name).filter(|f| *f != Func::Ln)?),
    })
}

/// Determinant by cofactor expansion (small matrices only).
fn determinant(
    ar: &mut crate::expr::Arena,
    d: &[ExprId],
    n: usize,
) -> Result<ExprId, crate::expr::ExprError> {
    if n == 1 {
        return Ok(d[0]);
    }
    let mut terms = Vec::with_capacity(n);
    for j in 0..n {
        let minor: Vec<ExprId> = (1..n)
            .flat_map(|i| (0..n).filter(move |&k| k != j).map(move |k| (i, k)))
            .map(|(i, k)| d[i * n + k])
            .collect();
        let m = determinant(ar, &minor, n - 1)?;
        let t = ar.mul(&[d[j], m])?;
        terms.push(if j % 2 == 1 { ar.neg(t)? } else { t });
    }
    ar.add(&terms)
}
