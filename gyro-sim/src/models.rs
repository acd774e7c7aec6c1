//! The models this simulator knows, compiled from their model files at build time.

use kane_model::runtime::GeneratedModel;

/// The 3-DOF gimballed gyroscope of the paper.
pub mod gimbal_gyroscope {
    kane_derive::model!("../kane-model/models/gimbal_gyroscope.al");
}

/// The EJS heavy symmetric top.
pub mod heavy_top {
    kane_derive::model!("../kane-model/models/heavy_top.al");
}

/// The names of the compiled models.
pub const MODEL_NAMES: &[&str] = &[gimbal_gyroscope::Model::NAME, heavy_top::Model::NAME];
