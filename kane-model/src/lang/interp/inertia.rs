//! The INERTIA statement: a body's central inertia by its moments and products, or (an
//! extension) by the shape of a uniform body.
//!
//! In: `INERTIA B, I11, I22, I33 [, I12, I23, I31]` or `INERTIA B, SHAPE(dimensions)`. Out: the
//! body's inertia dyadic about its mass centre, in its own frame, set on the model.

use crate::mechanics::{BodyId, Dyadic, Shape};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::{entity_key, At, Binding, IResult, Interpreter};

impl Interpreter {
    /// `INERTIA B, I11, I22, I33 [, I12, I23, I31]`: central inertia in B's frame.
    pub(crate) fn inertia(&mut self, body: &str, span: &Span, args: &[Expr]) -> IResult<()> {
        let key = body.to_ascii_uppercase();
        let Some(Binding::Body(b)) = self.bindings.get(&entity_key(&key)).cloned() else {
            return Err(Diagnostic::error(span.clone(), format!("`{body}` is not a body"))
                .with_help("declare it with BODIES"));
        };
        self.sources.inertial.insert(key.clone(), span.clone());
        if let [Expr { kind: ExprKind::Call { name, args: dims }, span: shape_span }] = args {
            return self.inertia_by_shape(b, name, dims, shape_span);
        }
        if args.len() != 3 && args.len() != 6 {
            return Err(Diagnostic::error(
                span.clone(),
                format!("INERTIA takes 3 or 6 moments, got {}", args.len()),
            )
            .with_help("INERTIA B, I11, I22, I33 or INERTIA B, I11, I22, I33, I12, I23, I31"));
        }
        for a in args {
            self.implicit_constants(a)?;
        }
        let v = args.iter().map(|a| self.scalar(a)).collect::<IResult<Vec<_>>>()?;
        let z = self.model.ar.zero();
        let (p12, p23, p31) = if v.len() == 6 { (v[3], v[4], v[5]) } else { (z, z, z) };
        let frame = self.model.body(b).frame;
        let d = Dyadic::in_frame(frame, [[v[0], p12, p31], [p12, v[1], p23], [p31, p23, v[2]]]);
        self.model.set_inertia(b, d);
        Ok(())
    }

    /// Extension (Autolev has no inertia by shape): `INERTIA B, SOLID_ELLIPSOID(a, b, c)` and
    /// likewise SOLID_SPHERE(r), SOLID_CYLINDER(r, l), THIN_ROD(l), CUBOID(a, b, c),
    /// THIN_DISK(r): the central inertia of that uniform shape with the body's MASS, its axes
    /// along the body's 1, 2, 3 (axis 3 the symmetry axis).
    fn inertia_by_shape(&mut self, b: BodyId, name: &str, dims: &[Expr], span: &Span) -> IResult<()> {
        let upper = name.to_ascii_uppercase();
        let want = match upper.as_str() {
            "SOLID_ELLIPSOID" | "CUBOID" => 3,
            "SOLID_CYLINDER" => 2,
            "SOLID_SPHERE" | "THIN_ROD" | "THIN_DISK" => 1,
            _ => {
                return Err(Diagnostic::error(span.clone(), format!("unknown shape `{name}`"))
                    .with_help("shapes: SOLID_ELLIPSOID(a,b,c), SOLID_SPHERE(r), SOLID_CYLINDER(r,l), THIN_ROD(l), CUBOID(a,b,c), THIN_DISK(r)"))
            }
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
        let dy = self.model.shape_inertia(shape, m, body.frame).at(span)?;
        self.model.set_inertia(b, dy);
        Ok(())
    }
}
