//! DIRCOS and KINDIFFS: orientations by angle sequences, Euler or Rodrigues parameters, and the kinematic
//! equations that go with a frame's angular velocity.
//!
//! In: `DIRCOS(A, B, kind, angles...)` or `KINDIFFS(A, B, kind, angles...)`. Out: B oriented in
//! A, or the kinematic differential equations of the angles set on the model.

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{FrameId, Orientation};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::{At, IResult, Interpreter};

/// The orientation kinds DIRCOS and KINDIFFS name.
enum Kind {
    /// Euler parameters, Autolev order: vector part e1, e2, e3, then the scalar e4.
    Euler,
    /// Rodrigues parameters: `tan(angle/2)` times the axis' measure numbers.
    Rodrigues,
    Body([u8; 3]),
    Space([u8; 3]),
}

impl Kind {
    /// The orientation of this kind by the parameters (Euler parameters in Autolev's order).
    fn orientation(&self, p: &[ExprId]) -> Orientation {
        match *self {
            Kind::Euler => Orientation::EulerParameters([p[3], p[0], p[1], p[2]]),
            Kind::Rodrigues => Orientation::Rodrigues([p[0], p[1], p[2]]),
            Kind::Body(axes) => Orientation::BodyFixed { axes, angles: [p[0], p[1], p[2]] },
            Kind::Space(axes) => Orientation::SpaceFixed { axes, angles: [p[0], p[1], p[2]] },
        }
    }
}

fn kind(word: &str) -> Option<Kind> {
    if word == "EULER" {
        return Some(Kind::Euler);
    }
    if word == "RODRIGUES" {
        return Some(Kind::Rodrigues);
    }
    let (prefix, digits) = if let Some(d) = word.strip_prefix("BODY") {
        (true, d)
    } else {
        (false, word.strip_prefix("SPACE")?)
    };
    let axes: Vec<u8> = digits.bytes().map(|b| b.wrapping_sub(b'0')).collect();
    if axes.len() != 3
        || axes.iter().any(|a| !(1..=3).contains(a))
        || axes[0] == axes[1]
        || axes[1] == axes[2]
    {
        return None;
    }
    let axes = [axes[0], axes[1], axes[2]];
    Some(if prefix { Kind::Body(axes) } else { Kind::Space(axes) })
}

impl Interpreter {
    fn kind_arg(&mut self, e: &Expr) -> IResult<Kind> {
        if let ExprKind::Name { name, .. } = &e.kind {
            if let Some(k) = kind(&name.to_ascii_uppercase()) {
                return Ok(k);
            }
        }
        Err(Diagnostic::error(
            e.span.clone(),
            "expected EULER, RODRIGUES, BODYijk or SPACEijk (for example BODY123, SPACE312)",
        ))
    }

    fn orientation(&mut self, args: &[Expr], span: &Span) -> IResult<(FrameId, FrameId, Kind, Vec<ExprId>)> {
        if args.len() < 6 {
            return Err(Diagnostic::error(span.clone(), "expected (A, B, kind, angles...)"));
        }
        let a = self.frame_arg(&args[0])?;
        let b = self.frame_arg(&args[1])?;
        let k = self.kind_arg(&args[2])?;
        let want = if matches!(k, Kind::Euler) { 4 } else { 3 };
        if args.len() != 3 + want {
            return Err(Diagnostic::error(
                span.clone(),
                format!("this orientation takes {want} parameters, got {}", args.len() - 3),
            ));
        }
        let p = args[3..].iter().map(|x| self.scalar(x)).collect::<IResult<Vec<_>>>()?;
        Ok((a, b, k, p))
    }

    /// `DIRCOS(A, B, kind, ...)`: orients B relative to A.
    pub(crate) fn dircos(&mut self, args: &[Expr], span: &Span) -> IResult<()> {
        let (a, b, k, p) = self.orientation(args, span)?;
        self.model.orient(b, a, k.orientation(&p)).at(span)?;
        self.sources.orientation(a, b, span);
        Ok(())
    }

    /// `ANGVEL(A, B, kind, ...)`: B's angular velocity in A set to the rates of that rotation
    /// sequence (or Euler parameters) of the angles given.
    pub(crate) fn angvel_by_sequence(&mut self, args: &[Expr], span: &Span) -> IResult<()> {
        let (a, b, k, p) = self.orientation(args, span)?;
        let w = self.model.orientation_rates(&k.orientation(&p), b).at(span)?;
        self.assign_angular_velocity(b, a, &w, span)
    }

    /// The kinematic equations of a rotation sequence's angles `angles` from `w` (B's angular
    /// velocity, in B): the orientation's angular velocity `J q'` (linear in the angle rates)
    /// equals it. An angle the file gave a value (`Q4 = 0` before KINDIFFS) keeps it: the other
    /// rates are the least-squares solution `(J^T J)^-1 J^T w`, exact wherever `w` is one the
    /// remaining angles can make (which the consistency check then verifies).
    fn sequence_kinematics(
        &mut self,
        b: FrameId,
        kind: &Kind,
        w: &[ExprId; 3],
        angles: &[ExprId],
        span: &Span,
    ) -> IResult<()> {
        let implied = self.model.orientation_rates(&kind.orientation(angles), b).at(span)?;
        let implied = self.model.express(&implied, b).at(span)?;
        let ar = &mut self.model.ar;
        let moving: Vec<(ExprId, SymbolId)> = angles
            .iter()
            .filter_map(|q| ar.as_symbol(*q).map(|s| (*q, s)))
            .filter(|(_, s)| ar.symbol_info(*s).kind.depends_on_time())
            .collect();
        if moving.is_empty() {
            return Err(Diagnostic::error(span.clone(), "the angles must be declared variables"));
        }
        let rates =
            moving.iter().map(|(_, s)| ar.derivative_symbol(*s)).collect::<Result<Vec<_>, _>>().at(span)?;
        let solved = if rates.len() == 3 {
            let eqs: Vec<ExprId> =
                (0..3).map(|i| ar.sub(implied[i], w[i])).collect::<Result<_, _>>().at(span)?;
            ar.solve_linear(&eqs, &rates).at(span)?
        } else {
            let j: Vec<Vec<ExprId>> = implied
                .iter()
                .map(|x| ar.linear_coefficients(*x, &rates).map(|(c, _)| c))
                .collect::<Result<_, _>>()
                .at(span)?;
            let k = rates.len();
            let mut normal = vec![vec![ar.zero(); k]; k];
            let mut rhs = vec![vec![ar.zero()]; k];
            for r in 0..k {
                for c in 0..k {
                    let terms = (0..3)
                        .map(|i| ar.mul(&[j[i][r], j[i][c]]))
                        .collect::<Result<Vec<_>, _>>()
                        .at(span)?;
                    normal[r][c] = ar.add(&terms).at(span)?;
                }
                let terms =
                    (0..3).map(|i| ar.mul(&[j[i][r], w[i]])).collect::<Result<Vec<_>, _>>().at(span)?;
                rhs[r][0] = ar.add(&terms).at(span)?;
            }
            let x = ar.solve_matrix(&normal, &rhs).map_err(|_| {
                Diagnostic::error(
                    span.clone(),
                    "KINDIFFS: the angles' rates cannot be solved from the angular velocity",
                )
            })?;
            x.into_iter().map(|r| ar.trig_simplify(r[0])).collect::<Result<Vec<_>, _>>().at(span)?
        };
        for ((q, s), r) in moving.into_iter().zip(solved) {
            self.kinematic.push((s, r));
            self.model.set_kinematics(q, r).at(span)?;
        }
        Ok(())
    }

    /// `KINDIFFS(A, B, kind, ...)`: the kinematic equations that make the orientation's rates
    /// agree with W_B_A> as set (its measure numbers in B are usually the speeds).
    pub(crate) fn kindiffs(&mut self, args: &[Expr], span: &Span) -> IResult<()> {
        let (a, b, k, p) = self.orientation(args, span)?;
        let w = self.model.angular_velocity(b, a).at(span)?;
        let w = self.model.express(&w, b).at(span)?;
        let syms: Vec<ExprId> = p.clone();
        let rhs: Vec<ExprId> = match k {
            Kind::Euler => {
                // e' = 1/2 e (x) (0, w) with e = (e4; e1, e2, e3): ev' = (e4 w + ev x w)/2,
                // e4' = -(ev . w)/2.
                let ar = &mut self.model.ar;
                let half = ar.rational(1, 2).at(span)?;
                let (e1, e2, e3, e4) = (p[0], p[1], p[2], p[3]);
                let cross = [(e2, w[2], e3, w[1]), (e3, w[0], e1, w[2]), (e1, w[1], e2, w[0])];
                let mut out = Vec::with_capacity(4);
                for (i, (x1, y1, x2, y2)) in cross.iter().enumerate() {
                    let t0 = ar.mul(&[e4, w[i]]).at(span)?;
                    let t1 = ar.mul(&[*x1, *y1]).at(span)?;
                    let t2 = ar.mul(&[*x2, *y2]).at(span)?;
                    let s = ar.add(&[t0, t1]).at(span)?;
                    let s = ar.sub(s, t2).at(span)?;
                    out.push(ar.mul(&[half, s]).at(span)?);
                }
                let d0 = ar.mul(&[e1, w[0]]).at(span)?;
                let d1 = ar.mul(&[e2, w[1]]).at(span)?;
                let d2 = ar.mul(&[e3, w[2]]).at(span)?;
                let dot = ar.add(&[d0, d1, d2]).at(span)?;
                let mh = ar.rational(-1, 2).at(span)?;
                out.push(ar.mul(&[mh, dot]).at(span)?);
                out
            }
            _ => return self.sequence_kinematics(b, &k, &w, &syms, span),
        };
        for (q, r) in syms.iter().zip(rhs) {
            let s = self.model.ar.as_symbol(*q).ok_or_else(|| {
                Diagnostic::error(span.clone(), "the parameters must be declared variables")
            })?;
            self.kinematic.push((s, r));
            self.model.set_kinematics(*q, r).at(span)?;
        }
        Ok(())
    }
}
