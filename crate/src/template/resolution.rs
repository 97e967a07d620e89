//! Template resolutions.

use std::str::FromStr;

use super::error::TemplateError;

/// A template resolution: `base` is the MakeHuman skin as it is (13 380 vertices, 26 756
/// triangles); `fine` is two levels of interpolating subdivision (≈ 428K triangles, at or above
/// the paper's 328K).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Resolution {
    Base,
    Fine,
}

impl Resolution {
    /// Subdivision levels applied to the base mesh.
    pub fn levels(self) -> usize {
        match self {
            Resolution::Base => 0,
            Resolution::Fine => 2,
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Resolution::Base => "base",
            Resolution::Fine => "fine",
        }
    }
}

impl FromStr for Resolution {
    type Err = TemplateError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "base" => Ok(Resolution::Base),
            "fine" => Ok(Resolution::Fine),
            other => Err(TemplateError::Resolution(other.to_string())),
        }
    }
}
