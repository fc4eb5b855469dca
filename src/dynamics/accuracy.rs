//! The work-precision study.
