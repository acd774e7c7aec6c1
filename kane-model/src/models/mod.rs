//! Canonical systems built through the Rust API.

mod free_body;
mod gimbal;
mod heavy_top;
mod pendulum;
mod rolling_disk;

pub use free_body::FreeBody;
pub use gimbal::GimbalGyroscope;
pub use heavy_top::HeavyTop;
pub use pendulum::n_link_pendulum;
pub use rolling_disk::RollingDisk;
