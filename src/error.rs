//! The one error type: misuse (bad input, I/O, a file that does not parse).
//!
//! Physical outcomes ("never jams", "QP infeasible", "integrator gave up") are never errors;
//! they are values of the status enums of each model.

use std::path::PathBuf;

/// Everything that can go wrong before or around a computation.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A parameter is out of its valid range. `key` is the TOML key (the CLI adds the flag).
    #[error("invalid {key} = {value}: {reason}")]
    InvalidValue {
        key: String,
        value: String,
        reason: String,
    },

    /// A TOML file does not parse or has an unknown key.
    #[error("{path}:{line}:{column}: {message}")]
    Config {
        path: PathBuf,
        line: usize,
        column: usize,
        message: String,
    },

    /// A file could not be read or written; `action` says which ("read", "write", ...).
    #[error("cannot {action} {path}: {source}")]
    Io {
        action: &'static str,
        path: PathBuf,
        source: std::io::Error,
    },

    /// A request the tool cannot serve (yet), e.g. a model that is not built.
    #[error("{0}")]
    Unsupported(String),
}

impl Error {
    /// Shorthand for [`Error::InvalidValue`].
    pub fn invalid(key: &str, value: impl std::fmt::Display, reason: impl Into<String>) -> Self {
        Error::InvalidValue {
            key: key.to_string(),
            value: value.to_string(),
            reason: reason.into(),
        }
    }

    /// Wraps an I/O error with what was being done and the path it concerns.
    pub fn io(action: &'static str, path: impl Into<PathBuf>, source: std::io::Error) -> Self {
        Error::Io {
            action,
            path: path.into(),
            source,
        }
    }
}

/// Result with [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
