//! Inconsistent models are rejected with an error that names the entity and says why.

use kane_model::mechanics::{MechanicsError, Model, Orientation, Vector};

#[test]
fn a_frame_oriented_twice() {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let a = m.add_frame("A").unwrap();
    let q = m.ar.variable("q").unwrap();
    m.orient(a, n, Orientation::Axis { axis: 3, angle: q }).unwrap();
    let err = m.orient(a, n, Orientation::Axis { axis: 1, angle: q }).unwrap_err();
    assert_eq!(err, MechanicsError::FrameOrientedTwice { frame: "A".into(), parent: "N".into() });
    assert_eq!(err.to_string(), "frame A is already oriented relative to N; a frame is oriented once");
}

#[test]
fn a_cycle_of_orientations() {
    let mut m = Model::new("N");
    let a = m.add_frame("A").unwrap();
    let b = m.add_frame("B").unwrap();
    let q = m.ar.variable("q").unwrap();
    m.orient(b, a, Orientation::Axis { axis: 3, angle: q }).unwrap();
    let err = m.orient(a, b, Orientation::Axis { axis: 3, angle: q }).unwrap_err();
    assert!(
        matches!(&err, MechanicsError::OrientationCycle { frame, parent } if frame == "A" && parent == "B")
    );
    assert!(err.to_string().contains("makes a cycle"), "{err}");
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
