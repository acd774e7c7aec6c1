//! Inconsistent models are rejected with an error that names the entity and says why.

use kane_model::mechanics::{MechanicsError, Model, Orientation, Vector};

#[test]
fn a_frame_oriented_again_takes_the_later_orientation() {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let a = m.add_frame("A").unwrap();
    let q = m.ar.variable("q").unwrap();
    m.orient(a, n, Orientation::Axis { axis: 3, angle: q }).unwrap();
    let first = m.dcm(n, a).unwrap();
    m.orient(a, n, Orientation::Axis { axis: 1, angle: q }).unwrap();
    let later = m.dcm(n, a).unwrap();
    assert_ne!(first, later);
    assert_eq!(later[0][0], m.ar.one(), "a rotation about N1 keeps N1");
}

#[test]
fn a_loop_of_orientations() {
    let mut m = Model::new("N");
    let a = m.add_frame("A").unwrap();
    let b = m.add_frame("B").unwrap();
    let c = m.add_frame("C").unwrap();
    let q = m.ar.variable("q").unwrap();
    m.orient(b, a, Orientation::Axis { axis: 3, angle: q }).unwrap();
    m.orient(c, b, Orientation::Axis { axis: 3, angle: q }).unwrap();
    let err = m.orient(a, c, Orientation::Axis { axis: 3, angle: q }).unwrap_err();
    assert!(
        matches!(&err, MechanicsError::OrientationCycle { frame, parent } if frame == "A" && parent == "C")
    );
    assert!(err.to_string().contains("closes a loop"), "{err}");
}

#[test]
fn a_tree_written_from_its_leaves_turns_around() {
    // N -> F, then A -> B -> C, then C -> F: the chain A, B, C hangs from F.
    let mut m = Model::new("N");
    let n = m.newtonian();
    let [f, a, b, c] = ["F", "A", "B", "C"].map(|x| m.add_frame(x).unwrap());
    let q: Vec<_> = (1..=4).map(|i| m.ar.variable(&format!("q{i}")).unwrap()).collect();
    m.orient(f, n, Orientation::Axis { axis: 3, angle: q[0] }).unwrap();
    m.orient(b, a, Orientation::Axis { axis: 3, angle: q[1] }).unwrap();
    m.orient(c, b, Orientation::Axis { axis: 3, angle: q[2] }).unwrap();
    m.orient(f, c, Orientation::Axis { axis: 3, angle: q[3] }).unwrap();
    // N_A is a rotation about N3 by q1 - q4 - q3 - q2.
    let d = m.dcm(n, a).unwrap();
    let sum = m.ar.add(&[q[1], q[2], q[3]]).unwrap();
    let angle = m.ar.sub(q[0], sum).unwrap();
    let at = |m: &Model, e| m.ar.eval(&[e], |s| Some(0.1 * (s.index() as f64 + 1.0))).unwrap()[0];
    let (cos, sin) = (m.ar.cos(angle).unwrap(), m.ar.sin(angle).unwrap());
    assert!((at(&m, d[0][0]) - at(&m, cos)).abs() < 1e-14);
    assert!((at(&m, d[1][0]) - at(&m, sin)).abs() < 1e-14);
}

#[test]
fn frames_that_are_not_connected() {
    let mut m = Model::new("N");
    let a = m.add_frame("A").unwrap();
    let n = m.newtonian();
    let err = m.dcm(n, a).unwrap_err();
    assert_eq!(err, MechanicsError::NoOrientationPath { a: "N".into(), b: "A".into() });
}

#[test]
fn a_velocity_asked_of_a_point_with_no_path() {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let p = m.add_point("P").unwrap();
    let err = m.velocity(p, n).unwrap_err();
    assert_eq!(err, MechanicsError::VelocityUndefined { point: "P".into(), frame: "N".into() });
    assert!(err.to_string().starts_with("velocity of point P has not been defined in frame N"));
}

#[test]
fn a_body_with_no_mass() {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let b = m.add_body("B").unwrap();
    let q = m.ar.variable("q").unwrap();
    let u = m.ar.variable("u").unwrap();
    let f = m.body(b).frame;
    m.orient(f, n, Orientation::Axis { axis: 3, angle: q }).unwrap();
    let o = m.add_point("O").unwrap();
    m.fix_point(o, n);
    let cm = m.body(b).mass_center;
    m.set_position(cm, o, Vector::zero()).unwrap();
    m.set_coordinates(&[q]).unwrap();
    m.set_speeds(&[u]).unwrap();
    m.set_kinematics(q, u).unwrap();
    let err = m.kane().unwrap_err();
    assert_eq!(err, MechanicsError::MissingMass("B".into()));
    assert_eq!(err.to_string(), "B has no mass: give it one (MASS B = ...)");
}

#[test]
fn a_coordinate_without_kinematics_and_a_constant_as_speed() {
    let mut m = Model::new("N");
    let q = m.ar.variable("q").unwrap();
    let u = m.ar.variable("u").unwrap();
    m.set_coordinates(&[q]).unwrap();
    m.set_speeds(&[u]).unwrap();
    assert_eq!(m.kane().unwrap_err(), MechanicsError::MissingKinematics("q".into()));
    let k = m.ar.constant("k").unwrap();
    assert_eq!(m.set_speeds(&[k]).unwrap_err(), MechanicsError::NotAVariable("k".into()));
}

#[test]
fn a_point_located_from_itself() {
    let mut m = Model::new("N");
    let p = m.add_point("P").unwrap();
    assert_eq!(m.set_position(p, p, Vector::zero()).unwrap_err(), MechanicsError::PositionCycle("P".into()));
}

#[test]
fn a_point_located_from_several_points_stays_a_tree() {
    // Autolev files may locate O from P1 and then from P2: P2 hangs from O.
    let mut m = Model::new("N");
    let n = m.newtonian();
    let [p1, p2, o] = ["P1", "P2", "O"].map(|s| m.add_point(s).unwrap());
    let a = m.unit(n, 1);
    let b = m.unit(n, 2);
    m.set_position(o, p1, a.clone()).unwrap();
    m.set_position(o, p2, b.clone()).unwrap();
    let r = m.position(p2, p1).unwrap();
    let want = m.sub_vectors(&a, &b).unwrap();
    let diff = m.sub_vectors(&r, &want).unwrap();
    assert!(m.express(&diff, n).unwrap().iter().all(|x| m.ar.is_zero(*x)));
}
