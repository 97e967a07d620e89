//! The base template as the unit tests take it: the template, its rest positions and triangles
//! (copied out of its mesh), its rigid parts and its hands.

use nalgebra::Point3;

use crate::mesh::Mesh;
use crate::template::hand::{hands, Hand};
use crate::template::parts::{blend, parts, Part, PartPose};
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

impl BaseBody {
    /// The template's surface with its parts placed by `poses` (one per part, blended as
    /// [`blend`] does): a made-up scan of a posed body.
    pub fn posed(&self, poses: &[PartPose]) -> Mesh {
        Mesh::new(
            blend(&self.parts, poses, &self.rest),
            self.triangles.clone(),
        )
    }
}
