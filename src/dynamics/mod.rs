//! Model 3: dynamic simulation of the paper's Adams model (Section 4).
pub mod contact;
pub mod integrators;
pub mod params;
pub mod scene;
