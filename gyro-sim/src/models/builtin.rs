//! The models compiled into gyro-sim from their model files at build time
//! (`kane_derive::model!`). A new model is one module here and one line in
//! [`Registry::builtin`]. Each asks for everything the simulator can run it with: Taylor
//! coefficients (straight-line at the orders the Taylor stepper takes,
//! `kane_model::runtime::TAYLOR_UNROLLED_ORDERS`) and lanes.

use kane_model::runtime::GeneratedModel;

use super::generated::{generated_from_file, generated_with_mechanics};
use super::registry::Registry;

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

/// `M`, generated from the model file `name` in `kane-model/models/` whose text is `source`.
fn from_file<M: GeneratedModel + 'static>(
    registry: Registry,
    name: &'static str,
    source: &'static str,
) -> Registry {
    registry.with_entry(M::INFO.name, generated_from_file::<M>(name, source))
}

impl Registry {
    /// The models compiled into gyro-sim (those from model files with their file's text, to
    /// name the operation behind a failure).
    pub fn builtin() -> Registry {
        let registry = Registry::new();
        let registry = from_file::<gimbal_gyroscope::Model>(
            registry,
            "gimbal_gyroscope.al",
            include_str!("../../../kane-model/models/gimbal_gyroscope.al"),
        );
        let registry = from_file::<heavy_top::Model>(
            registry,
            "heavy_top.al",
            include_str!("../../../kane-model/models/heavy_top.al"),
        );
        let registry = from_file::<heavy_top_axle::Model>(
            registry,
            "heavy_top_axle.al",
            include_str!("../../../kane-model/models/heavy_top_axle.al"),
        );
        let top = generated_with_mechanics::<heavy_top_rust::Model>(|| {
            kane_model::models::HeavyTop::new().ok().map(|top| top.model)
        });
        let registry = registry.with_entry(heavy_top_rust::Model::INFO.name, top);
        from_file::<free_body::Model>(
            registry,
            "free_body.al",
            include_str!("../../../kane-model/models/free_body.al"),
        )
    }
}
