//! The INERTIA statement: a body's central inertia by its moments and products, or (an
//! extension) by the shape of a uniform body.
//!
//! In: `INERTIA B, I11, I22, I33 [, I12, I23, I31]`, `INERTIA B(A), ...`, `INERTIA B_P(A), ...`
//! or `INERTIA B, SHAPE(dimensions)`. Out: the body's inertia dyadic about its mass centre, set
//! on the model.
//!
//! What the names mean (Autolev's, as SymPy's Autolev grammar reads them: `INERTIA ID ('(' ID
//! ')')? (',' expr)+`, with the name in parentheses a frame and `B_P` a body and a point): the
//! moments and products are measure numbers in the unit vectors of the frame in parentheses,
//! A (B's own when none is named: `I11 A1>*A1> + I12 (A1>*A2> + A2>*A1>) + ...`); `B_P` gives
//! them about the point P, and the central inertia is `I_B_P - m (r.r 1 - r r)` with `r` from P
//! to BO (parallel axes), which needs B's MASS given and BO located from P first.

use crate::expr::SymbolKind;
use crate::mechanics::{BodyId, Dyadic, FrameId, PointId, Shape};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::{entity_key, At, Binding, IResult, Interpreter};

/// The shapes `INERTIA B, SHAPE(dimensions)` knows, with how many dimensions each takes.
pub(crate) const SHAPES: &[(&str, usize)] = &[
    ("CUBOID", 3),
    ("SOLID_CYLINDER", 2),
    ("SOLID_ELLIPSOID", 3),
    ("SOLID_SPHERE", 1),
    ("THIN_DISK", 1),
    ("THIN_ROD", 1),
];

impl Interpreter {
    /// `INERTIA B[_P][(A)], I11, I22, I33 [, I12, I23, I31]`: B's central inertia.
    pub(crate) fn inertia(
        &mut self,
        body: &str,
        span: &Span,
        frame: Option<&(String, Span)>,
        args: &[Expr],
    ) -> IResult<()> {
        let (b, about) = self.inertia_body(body, span)?;
        let frame = match frame {
            Some((name, at)) => self.inertia_frame(name, at, body)?,
            None => self.model.body(b).frame,
        };
        self.sources.inertial.insert(self.model.body(b).name.to_ascii_uppercase(), span.clone());
        if let [Expr { kind: ExprKind::Call { name, args: dims }, span: shape_span }] = args {
            if about.is_some() {
                return Err(Diagnostic::error(
                    span.clone(),
                    "INERTIA by shape gives the inertia about the mass centre",
                )
                .with_help("name the body alone: INERTIA B, SHAPE(...) or INERTIA B(A), SHAPE(...)"));
            }
            return self.inertia_by_shape(b, frame, name, dims, shape_span);
        }
        if args.len() != 3 && args.len() != 6 {
            return Err(Diagnostic::error(
                span.clone(),
                format!("INERTIA takes 3 or 6 moments, got {}", args.len()),
            )
            .with_help("INERTIA B, I11, I22, I33 or INERTIA B, I11, I22, I33, I12, I23, I31"));
        }
        let mut v = Vec::with_capacity(args.len());
        for a in args {
            let a = self.inline_definition(a)?;
            self.implicit_constants(a)?;
            v.push(self.scalar(a)?);
        }
        let z = self.model.ar.zero();
        let (p12, p23, p31) = if v.len() == 6 { (v[3], v[4], v[5]) } else { (z, z, z) };
        let d = Dyadic::in_frame(frame, [[v[0], p12, p31], [p12, v[1], p23], [p31, p23, v[2]]]);
        match about {
            // Where BO is from P may come later: the central inertia waits for the equations.
            Some(p) if self.model.position(self.model.body(b).mass_center, p).is_err() => {
                self.pending_inertias.push((b, p, d, frame, span.clone()));
            }
            Some(p) => {
                let d = self.central_from(b, p, &d, frame, span)?;
                self.model.set_inertia(b, d);
            }
            None => self.model.set_inertia(b, d),
        }
        Ok(())
    }

    /// The central inertias of `INERTIA B_P` statements given before BO was located from P.
    pub(crate) fn settle_inertias(&mut self) -> IResult<()> {
        for (b, p, d, frame, span) in std::mem::take(&mut self.pending_inertias) {
            let d = self.central_from(b, p, &d, frame, &span)?;
            self.model.set_inertia(b, d);
        }
        Ok(())
    }

    /// The body `B` that `B` or `B_P` names, and the point `P` if named.
    fn inertia_body(&mut self, body: &str, span: &Span) -> IResult<(BodyId, Option<PointId>)> {
        let key = body.to_ascii_uppercase();
        let body_of = |me: &Self, k: &str| match me.bindings.get(&entity_key(k)) {
            Some(Binding::Body(b)) => Some(*b),
            _ => None,
        };
        if let Some(b) = body_of(self, &key) {
            return Ok((b, None));
        }
        self.frame_origins_in(&key);
        let split = key
            .match_indices('_')
            .find_map(|(i, _)| Some((body_of(self, &key[..i])?, self.point_of(&key[i + 1..])?)));
        match split {
            Some((b, p)) if p == self.model.body(b).mass_center => Ok((b, None)),
            Some((b, p)) => Ok((b, Some(p))),
            None => Err(Diagnostic::error(span.clone(), format!("`{body}` is not a body"))
                .with_help("declare it with BODIES; INERTIA B_P, ... gives body B's inertia about point P")),
        }
    }

    /// The frame named in `INERTIA B(A)`.
    fn inertia_frame(&mut self, name: &str, at: &Span, body: &str) -> IResult<FrameId> {
        let key = name.to_ascii_uppercase();
        if let Some(f) = self.frame_of(&key) {
            return Ok(f);
        }
        let d = Diagnostic::error(
            at.clone(),
            format!(
                "`{name}` is not a frame: INERTIA's parentheses name the frame the moments are measured in"
            ),
        );
        Err(if self.point_of(&key).is_some() {
            d.with_help(format!("for the inertia about point {name}, write INERTIA {body}_{name}, ... (or {body}_{name}(A) for frame A's unit vectors)"))
        } else {
            d.with_help("frames are declared with NEWTONIAN, FRAMES or BODIES")
        })
    }

    /// B's central inertia from `about_p`, its inertia about P: `I - m (r.r 1 - r r)` with `r`
    /// from P to BO, which must be fixed in B.
    fn central_from(
        &mut self,
        b: BodyId,
        p: PointId,
        about_p: &Dyadic,
        frame: FrameId,
        span: &Span,
    ) -> IResult<Dyadic> {
        let body = self.model.body(b).clone();
        let (name, point) = (body.name.clone(), self.model.point_name(p).to_string());
        let m = body.mass.ok_or_else(|| {
            Diagnostic::error(
                span.clone(),
                format!(
                    "{name} has no mass yet: INERTIA {name}_{point} needs it to find the central inertia"
                ),
            )
            .with_help(format!("give MASS {name} = ... before INERTIA {name}_{point}"))
        })?;
        let r = self.model.position(body.mass_center, p).map_err(|_| {
            Diagnostic::error(span.clone(), format!("INERTIA {name}_{point} needs where {name}O is from {point}, which is not known yet"))
                .with_help(format!("locate {name}O from {point} first (P_{point}_{name}O> = ...), or give the central inertia: INERTIA {name}, ..."))
        })?;
        let in_body = self.model.express(&r, body.frame).at(span)?;
        let ar = &self.model.ar;
        if ar.free_symbols(&in_body).iter().any(|s| !matches!(ar.symbol_info(*s).kind, SymbolKind::Constant))
        {
            return Err(Diagnostic::error(span.clone(), format!("{point} moves in {name}: the inertia about it changes, so INERTIA {name}_{point} has no meaning"))
                .with_help(format!("give the inertia about a point fixed in {name}, or about {name}O")));
        }
        let minus_m = self.model.ar.neg(m).at(span)?;
        self.model.parallel_axis(about_p, minus_m, &r, frame).at(span)
    }

    /// Extension (Autolev has no inertia by shape): `INERTIA B, SOLID_ELLIPSOID(a, b, c)` and
    /// likewise SOLID_SPHERE(r), SOLID_CYLINDER(r, l), THIN_ROD(l), CUBOID(a, b, c),
    /// THIN_DISK(r): the central inertia of that uniform shape with the body's MASS, its axes
    /// along `frame`'s 1, 2, 3 (the body's, or A's in `INERTIA B(A)`; axis 3 the symmetry axis).
    fn inertia_by_shape(
        &mut self,
        b: BodyId,
        frame: FrameId,
        name: &str,
        dims: &[Expr],
        span: &Span,
    ) -> IResult<()> {
        let upper = name.to_ascii_uppercase();
        let Some(&(_, want)) = SHAPES.iter().find(|(s, _)| *s == upper) else {
            return Err(Diagnostic::error(span.clone(), format!("unknown shape `{name}`"))
                .with_help("shapes: SOLID_ELLIPSOID(a,b,c), SOLID_SPHERE(r), SOLID_CYLINDER(r,l), THIN_ROD(l), CUBOID(a,b,c), THIN_DISK(r)"));
        };
        if dims.len() != want {
            return Err(Diagnostic::error(
                span.clone(),
                format!("{upper} takes {want} dimension(s), got {}", dims.len()),
            ));
        }
        let d = dims.iter().map(|x| self.scalar(x)).collect::<IResult<Vec<_>>>()?;
        let shape = match upper.as_str() {
            "SOLID_ELLIPSOID" => Shape::SolidEllipsoid { a: d[0], b: d[1], c: d[2] },
            "CUBOID" => Shape::Cuboid { a: d[0], b: d[1], c: d[2] },
            "SOLID_CYLINDER" => Shape::SolidCylinder { r: d[0], l: d[1] },
            "SOLID_SPHERE" => Shape::SolidSphere { r: d[0] },
            "THIN_ROD" => Shape::ThinRod { l: d[0] },
            _ => Shape::ThinDisk { r: d[0] },
        };
        let body = self.model.body(b).clone();
        let m = body.mass.ok_or_else(|| {
            Diagnostic::error(span.clone(), format!("{} has no mass yet", body.name))
                .with_help("give MASS before INERTIA by shape")
        })?;
        let dy = self.model.shape_inertia(shape, m, frame).at(span)?;
        self.model.set_inertia(b, dy);
        Ok(())
    }
}
