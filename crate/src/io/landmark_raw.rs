//! A landmark as a format reader (CSV, `.lnd`, JSON) found it, before names are normalised, and
//! the finiteness check every reader applies to its coordinates.

use nalgebra::Point3;

use super::IoError;

/// A landmark as a reader found it, before names are normalised.
#[derive(Debug, Clone, PartialEq)]
pub struct RawLandmark {
    /// The name as written in the file.
    pub name: String,
    /// `None` when the file marks it as missing.
    pub position: Option<Point3<f64>>,
}

/// Checks that a coordinate triple is finite, naming the landmark otherwise.
pub(crate) fn finite(p: [f64; 3], name: &str, file: &str) -> Result<Point3<f64>, IoError> {
    if p.iter().all(|c| c.is_finite()) {
        Ok(Point3::new(p[0], p[1], p[2]))
    } else {
        Err(IoError::NonFinite {
            file: file.to_string(),
            what: format!("landmark {name:?}"),
        })
    }
}
