//! Length units of a scan, detected from the body's extent.
//!
//! An adult or child body is 0.5–2.5 m along its largest bounding-box side. A largest extent above
//! [`MILLIMETRE_THRESHOLD`] cannot be metres (a 10 m body) but is a plausible 0.01–2.5 m in
//! millimetres, so the file is taken to be in millimetres; anything smaller is taken as metres.

use serde::{Deserialize, Serialize};

/// Largest bounding-box extent (in file units) still read as metres.
pub const MILLIMETRE_THRESHOLD: f64 = 10.0;

/// The length unit of a file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    Metres,
    Millimetres,
}

impl Units {
    /// The factor that converts a length in these units to metres.
    pub fn scale_to_metres(self) -> f64 {
        match self {
            Units::Metres => 1.0,
            Units::Millimetres => 1e-3,
        }
    }

    /// `"metres"` or `"millimetres"`, as serialised.
    pub fn name(self) -> &'static str {
        match self {
            Units::Metres => "metres",
            Units::Millimetres => "millimetres",
        }
    }
}

/// The units of a body whose largest bounding-box side is `extent` (in file units).
pub fn detect_units(extent: f64) -> Units {
    if extent > MILLIMETRE_THRESHOLD {
        Units::Millimetres
    } else {
        Units::Metres
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bodies_in_metres_and_millimetres() {
        assert_eq!(detect_units(1.75), Units::Metres);
        assert_eq!(detect_units(0.6), Units::Metres);
        assert_eq!(detect_units(2.4), Units::Metres);
        assert_eq!(detect_units(1750.0), Units::Millimetres);
        assert_eq!(detect_units(520.0), Units::Millimetres);
        assert_eq!(detect_units(0.0), Units::Metres);
        assert_eq!(Units::Millimetres.scale_to_metres(), 1e-3);
    }

    #[test]
    fn serialises_lowercase() {
        assert_eq!(
            serde_json::to_string(&Units::Millimetres).unwrap(),
            "\"millimetres\""
        );
        assert_eq!(serde_json::to_string(&Units::Metres).unwrap(), "\"metres\"");
    }
}
