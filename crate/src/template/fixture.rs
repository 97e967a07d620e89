//! The base template as the unit tests take it: the template, its rest positions and triangles
//! (copied out of its mesh), its rigid parts and its hands.

use nalgebra::Point3;

use crate::template::hand::{hands, Hand};
use crate::template::parts::{parts, Part};
use crate::template::{Resolution, Template};

/// The embedded template at base resolution with what the tests read from it.
pub(crate) struct BaseBody {
    pub template: Template,
    /// The template's vertex positions (template frame, metres), `#V`.
    pub rest: Vec<Point3<f64>>,
    /// Its triangles, `#F` vertex index triples.
    pub triangles: Vec<[u32; 3]>,
    /// Its rigid parts (`template::parts`).
    pub parts: Vec<Part>,
    /// Its two hands (`template::hand`).
    pub hands: Vec<Hand>,
}

/// The embedded template at base resolution, its parts and its hands.
pub(crate) fn base_body() -> BaseBody {
    let template = Template::embedded()
        .unwrap()
        .at_resolution(Resolution::Base);
    BaseBody {
        rest: template.mesh().positions.clone(),
        triangles: template.mesh().triangles.clone(),
        parts: parts(&template),
        hands: hands(&template),
        template,
    }
}
