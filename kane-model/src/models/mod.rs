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

/// The spec of a canonical system by name (for `kane_derive::model!(builtin = "...")`), or
/// None for an unknown name.
pub fn builtin_spec(name: &str) -> Option<crate::mechanics::Result<crate::spec::ModelSpec>> {
    match name {
        HeavyTop::SPEC_NAME => Some(HeavyTop::new().and_then(HeavyTop::spec)),
        _ => None,
    }
}

/// The names [`builtin_spec`] knows.
pub const BUILTIN_SPECS: &[&str] = &[HeavyTop::SPEC_NAME];
