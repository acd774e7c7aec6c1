//! The models compiled into gyro-sim from their model files at build time
//! (`kane_derive::model!`). A new model is one module here and one line in
//! [`Registry::builtin`]. Each asks for everything the simulator can run it with: Taylor
//! coefficients (straight-line at the orders the Taylor stepper takes,
//! `kane_model::runtime::TAYLOR_UNROLLED_ORDERS`) and lanes.

use kane_model::runtime::GeneratedModel;

use super::registry::Registry;
use crate::problem::{MechanicsSource, ModelEntry};

/// The 3-DOF gimballed gyroscope of the paper.
pub mod gimbal_gyroscope {
    kane_derive::model!(
        "../kane-model/models/gimbal_gyroscope.al",
        taylor,
        lanes,
        taylor_orders = [8, 12, 14, 16, 20]
    );
}

/// The EJS heavy symmetric top.
pub mod heavy_top {
    kane_derive::model!(
        "../kane-model/models/heavy_top.al",
        taylor,
        lanes,
        taylor_orders = [8, 12, 14, 16, 20]
    );
}

/// A torque-free rigid body (EJS "Free Rotation", Feynman's plate): Euler parameters and body
/// rates, principal moments I1, I2, I3.
pub mod free_body {
    kane_derive::model!(
        "../kane-model/models/free_body.al",
        taylor,
        lanes,
        taylor_orders = [8, 12, 14, 16, 20]
    );
}

/// The EJS heavy symmetric top in its non-spinning axle frame: the spin angle is cyclic, so the
/// step follows the nutation (spin-aware).
pub mod heavy_top_axle {
    kane_derive::model!(
        "../kane-model/models/heavy_top_axle.al",
        taylor,
        lanes,
        taylor_orders = [8, 12, 14, 16, 20]
    );
}

/// The same top built through kane-model's Rust API (`kane_model::models::HeavyTop`), with
/// energy, angular-momentum and orientation outputs.
pub mod heavy_top_rust {
    kane_derive::builtin_model!("heavy_top_rust", taylor, lanes, taylor_orders = [8, 12, 14, 16, 20]);
}

impl Registry {
    /// The models compiled into gyro-sim (those from model files with their file's text, to
    /// name the operation behind a failure).
    pub fn builtin() -> Registry {
        Registry::new()
            .with_entry_of::<gimbal_gyroscope::Model>(Some((
                "gimbal_gyroscope.al",
                include_str!("../../../kane-model/models/gimbal_gyroscope.al"),
            )))
            .with_entry_of::<heavy_top::Model>(Some((
                "heavy_top.al",
                include_str!("../../../kane-model/models/heavy_top.al"),
            )))
            .with_entry_of::<heavy_top_axle::Model>(Some((
                "heavy_top_axle.al",
                include_str!("../../../kane-model/models/heavy_top_axle.al"),
            )))
            .with_entry(
                heavy_top_rust::Model::INFO.name,
                ModelEntry::of::<heavy_top_rust::Model>().with_mechanics(MechanicsSource::new(|| {
                    kane_model::models::HeavyTop::new().ok().map(|top| top.model)
                })),
            )
            .with_entry_of::<free_body::Model>(Some((
                "free_body.al",
                include_str!("../../../kane-model/models/free_body.al"),
            )))
    }
}
