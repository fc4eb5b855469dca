//! What the integration tests share: running the binary, browsers and the gallery's page,
//! random boxes and contact problems, the 25 mm shaft.

pub mod boxes;
pub mod browser;
pub mod cli;
#[macro_use]
pub mod gallery;
pub mod random_planar;
pub mod shaft;
