//! The six overlapping body segments of paper §4.2.1.

use serde::{Deserialize, Serialize};

/// A body segment. Neighbouring segments overlap in bands so that segment reconstructions can be
/// stitched with blend weights.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Segment {
    Head,
    LeftArm,
    RightArm,
    Torso,
    LeftLeg,
    RightLeg,
}

impl Segment {
    /// All six segments in their canonical order.
    pub const ALL: [Segment; 6] = [
        Segment::Head,
        Segment::LeftArm,
        Segment::RightArm,
        Segment::Torso,
        Segment::LeftLeg,
        Segment::RightLeg,
    ];

    /// The snake_case name used in files, links and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Segment::Head => "head",
            Segment::LeftArm => "left_arm",
            Segment::RightArm => "right_arm",
            Segment::Torso => "torso",
            Segment::LeftLeg => "left_leg",
            Segment::RightLeg => "right_leg",
        }
    }

    /// Parses a snake_case segment name.
    pub fn from_name(name: &str) -> Option<Segment> {
        Segment::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Index of this segment in [`Segment::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}
