//! The uniform solid ellipsoid of a body's mass and central inertia: in come the mass and the
//! inertia's six entries in the body's axes (numbers); out go the ellipsoid's semi-axes
//! (`a^2 = 5/(2m) (I2 + I3 - I1)`, cyclically, from the principal moments) and, when the inertia
//! has products, its principal axes in the body's axes.

use nalgebra::{Matrix3, SymmetricEigen};

/// No semi-axis is shorter than this fraction of the longest: an inertia no solid has (a planar
/// link's `0, 0, I3`, a thin rod's) is drawn as a flat disc or a needle.
const THINNEST: f64 = 0.02;

/// A uniform solid ellipsoid in a body's axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InertiaEllipsoid {
    /// Its semi-axes, along its own axes 1, 2, 3.
    pub semi_axes: [f64; 3],
    /// Its axes in the body's axes, a rotation row by row (`B_i . E_j`); none when they are the
    /// body's.
    pub axes: Option<[f64; 9]>,
}

/// The ellipsoid of mass `mass` and central inertia `inertia` (I11, I22, I33, I12, I23, I31 in
/// the body's axes); none for a body without mass, without moments, or with a value not finite.
pub fn inertia_ellipsoid(mass: f64, inertia: [f64; 6]) -> Option<InertiaEllipsoid> {
    if !(mass > 0.0 && mass.is_finite() && inertia.iter().all(|x| x.is_finite())) {
        return None;
    }
    let [i11, i22, i33, i12, i23, i31] = inertia;
    let (moments, axes) = if [i12, i23, i31] == [0.0; 3] {
        ([i11, i22, i33], None)
    } else {
        let eigen = SymmetricEigen::new(Matrix3::new(i11, i12, i31, i12, i22, i23, i31, i23, i33));
        let mut v = eigen.eigenvectors;
        if v.determinant() < 0.0 {
            v.column_mut(2).neg_mut();
        }
        let e = eigen.eigenvalues;
        ([e[0], e[1], e[2]], Some(std::array::from_fn(|k| v[(k / 3, k % 3)])))
    };
    let sum: f64 = moments.iter().sum();
    let squares = moments.map(|i| 2.5 / mass * (sum - 2.0 * i));
    let longest = squares.iter().copied().fold(0.0, f64::max).sqrt();
    if !(longest > 0.0 && longest.is_finite()) {
        return None;
    }
    let semi_axes = squares.map(|s| s.max(0.0).sqrt().max(THINNEST * longest));
    Some(InertiaEllipsoid { semi_axes, axes })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(got: [f64; 3], want: [f64; 3]) {
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-12 * w.max(1.0), "{got:?} against {want:?}");
        }
    }

    /// The moments of the solid ellipsoid of mass `m` with semi-axes `a`.
    fn moments(m: f64, [a, b, c]: [f64; 3]) -> [f64; 3] {
        [m / 5.0 * (b * b + c * c), m / 5.0 * (a * a + c * c), m / 5.0 * (a * a + b * b)]
    }

    #[test]
    fn a_sphere_and_an_ellipsoid_give_back_their_semi_axes() {
        let sphere = inertia_ellipsoid(2.0, [0.072, 0.072, 0.072, 0.0, 0.0, 0.0]).unwrap();
        close(sphere.semi_axes, [0.3; 3]);
        assert_eq!(sphere.axes, None);
        let [i1, i2, i3] = moments(5.0, [1.0, 2.0, 3.0]);
        close(inertia_ellipsoid(5.0, [i1, i2, i3, 0.0, 0.0, 0.0]).unwrap().semi_axes, [1.0, 2.0, 3.0]);
    }

    #[test]
    fn a_box_gives_the_ellipsoid_of_its_inertia() {
        // Edges x, y, z: I1 = m (y^2 + z^2) / 12, ...; the ellipsoid's a = x sqrt(5/12).
        let (m, [x, y, z]) = (3.0, [0.4, 1.0, 2.0]);
        let i = [m * (y * y + z * z) / 12.0, m * (x * x + z * z) / 12.0, m * (x * x + y * y) / 12.0];
        let e = inertia_ellipsoid(m, [i[0], i[1], i[2], 0.0, 0.0, 0.0]).unwrap();
        close(e.semi_axes, [x, y, z].map(|s| s * (5.0f64 / 12.0).sqrt()));
    }

    #[test]
    fn an_inertia_with_products_is_drawn_along_its_principal_axes() {
        // The ellipsoid 1, 2, 3 turned by 0.5 rad about body axis 3: I = R diag R^T.
        let (c, s) = (0.5f64.cos(), 0.5f64.sin());
        let [i1, i2, i3] = moments(5.0, [1.0, 2.0, 3.0]);
        let inertia = [c * c * i1 + s * s * i2, s * s * i1 + c * c * i2, i3, c * s * (i1 - i2), 0.0, 0.0];
        let e = inertia_ellipsoid(5.0, inertia).unwrap();
        let axes = e.axes.expect("turned");
        let column = |j: usize| [axes[j], axes[3 + j], axes[6 + j]];
        let det = Matrix3::from_row_slice(&axes).determinant();
        assert!((det - 1.0).abs() < 1e-12, "a rotation: {axes:?}");
        for (semi, along) in [(1.0, [c, s, 0.0]), (2.0, [-s, c, 0.0]), (3.0, [0.0, 0.0, 1.0])] {
            let j = e.semi_axes.iter().position(|a| (a - semi).abs() < 1e-12).expect("each semi-axis");
            let cosine: f64 = column(j).iter().zip(along).map(|(x, y)| x * y).sum();
            assert!((cosine.abs() - 1.0).abs() < 1e-12, "semi-axis {semi} along {:?}", column(j));
        }
    }

    #[test]
    fn a_planar_link_is_a_disc_and_a_thin_rod_a_needle() {
        let disc = inertia_ellipsoid(2.0, [0.0, 0.0, 0.5, 0.0, 0.0, 0.0]).unwrap();
        let a = (2.5f64 / 2.0 * 0.5).sqrt();
        close(disc.semi_axes, [a, a, THINNEST * a]);
        let rod = inertia_ellipsoid(1.0, [0.0, 1.0 / 12.0, 1.0 / 12.0, 0.0, 0.0, 0.0]).unwrap();
        let a = (5.0f64 / 12.0).sqrt();
        close(rod.semi_axes, [a, THINNEST * a, THINNEST * a]);
        // Moments breaking the triangle inequality: finite and positive all the same.
        let broken = inertia_ellipsoid(1.0, [1.0, 1.0, 5.0, 0.0, 0.0, 0.0]).unwrap();
        assert!(broken.semi_axes.iter().all(|s| s.is_finite() && *s > 0.0), "{broken:?}");
    }

    #[test]
    fn no_mass_no_moments_or_a_value_not_finite_is_no_ellipsoid() {
        let unit = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0];
        for mass in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(inertia_ellipsoid(mass, unit), None, "mass {mass}");
        }
        assert_eq!(inertia_ellipsoid(1.0, [0.0; 6]), None);
        assert_eq!(inertia_ellipsoid(1.0, [f64::NAN, 1.0, 1.0, 0.0, 0.0, 0.0]), None);
        assert_eq!(inertia_ellipsoid(1.0, [1.0, 1.0, 1.0, f64::NAN, 0.0, 0.0]), None);
        assert_eq!(inertia_ellipsoid(1.0, [-1.0, -1.0, -1.0, 0.0, 0.0, 0.0]), None);
        assert_eq!(inertia_ellipsoid(1e-300, [1e10, 1e10, 1e10, 0.0, 0.0, 0.0]), None, "overflow");
    }
}
