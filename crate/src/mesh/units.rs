//! Length units of a scan, detected from the body's extent.
//!
//! An adult or child body is 0.5–2.5 m along its largest bounding-box side. A largest extent above
//! [`CENTIMETRE_THRESHOLD`] cannot be metres (a 10 m body); up to [`MILLIMETRE_THRESHOLD`] it is
//! a plausible 0.1–3 m in centimetres (50–250 for a body), above it 0.3 m or more in millimetres
//! (500–2500 for a body). The three ranges of a real body do not overlap.

use serde::{Deserialize, Serialize};

/// Largest bounding-box extent (in file units) still read as metres.
pub const CENTIMETRE_THRESHOLD: f64 = 10.0;

/// Largest bounding-box extent (in file units) still read as centimetres.
pub const MILLIMETRE_THRESHOLD: f64 = 300.0;

/// The length unit of a file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    Metres,
    Centimetres,
    Millimetres,
}

impl Units {
    /// The factor that converts a length in these units to metres.
    pub fn scale_to_metres(self) -> f64 {
        match self {
            Units::Metres => 1.0,
            Units::Centimetres => 1e-2,
            Units::Millimetres => 1e-3,
        }
    }

    /// `"metres"`, `"centimetres"` or `"millimetres"`, as serialised.
    pub fn name(self) -> &'static str {
        match self {
            Units::Metres => "metres",
            Units::Centimetres => "centimetres",
            Units::Millimetres => "millimetres",
        }
    }
}

/// The units of a body whose largest bounding-box side is `extent` (in file units).
pub fn detect_units(extent: f64) -> Units {
    if extent > MILLIMETRE_THRESHOLD {
        Units::Millimetres
    } else if extent > CENTIMETRE_THRESHOLD {
        Units::Centimetres
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
        assert_eq!(detect_units(175.0), Units::Centimetres);
        assert_eq!(detect_units(52.0), Units::Centimetres);
        assert_eq!(detect_units(240.0), Units::Centimetres);
        assert_eq!(Units::Centimetres.scale_to_metres(), 1e-2);
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
