//! Canonical systems built through the Rust API.

mod gimbal;
mod heavy_top;
mod pendulum;

pub use gimbal::GimbalGyroscope;
pub use heavy_top::HeavyTop;
pub use pendulum::n_link_pendulum;
