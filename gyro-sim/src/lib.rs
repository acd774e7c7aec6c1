//! gyro-sim: integrators, scenes and outputs for models derived with kane-model.
//!
//! Not implemented yet: see the code-generation and simulation issue.
