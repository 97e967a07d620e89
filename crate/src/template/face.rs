//! The template's face: its nose tip (pronasale), the point of the face that stands out most.
//! The landmark estimate's segment-wise fit pulls it to the scan's nose tip (`mesh::tip`,
//! `estimate/segments.rs`): nearest points slide a head's surface over the scan's head freely,
//! the nose tip does not slide.

use crate::template::{Segment, Template};

/// A vertex this close (m) to x = 0 lies on the template's midline (the template is symmetric).
const MIDLINE: f64 = 1e-4;

/// The template's nose tip: of its midline vertices wholly in the head segment and between the
/// heights of its Supramenton and its Sellion, the one farthest forward (+z, the template frame at
/// rest). `None` when the template lacks either landmark or any such vertex.
pub fn nose_tip(template: &Template) -> Option<u32> {
    let rest = &template.mesh().positions;
    let height = |name: &str| template.landmark_vertex(name).map(|v| rest[v as usize].y);
    let (low, high) = (height("Supramenton")?, height("Sellion")?);
    (0..rest.len() as u32)
        .filter(|&v| {
            let p = rest[v as usize];
            p.x.abs() < MIDLINE
                && p.y > low
                && p.y < high
                && template.segment_weights(v)[Segment::Head.index()] >= 1.0
        })
        .max_by(|&a, &b| rest[a as usize].z.total_cmp(&rest[b as usize].z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nose_tip_stands_forward_of_the_face_on_the_midline() {
        let template = Template::embedded().unwrap();
        let v = nose_tip(&template).expect("a nose tip");
        let rest = &template.mesh().positions;
        let tip = rest[v as usize];
        let sellion = rest[template.landmark_vertex("Sellion").unwrap() as usize];
        let chin = rest[template.landmark_vertex("Supramenton").unwrap() as usize];
        assert!(tip.x.abs() < MIDLINE);
        // A nose stands 1.5–3 cm in front of the nasal root and the chin's groove.
        assert!(
            tip.z - sellion.z > 0.01 && tip.z - sellion.z < 0.04,
            "{tip} {sellion}"
        );
        assert!(
            tip.z - chin.z > 0.01 && tip.z - chin.z < 0.05,
            "{tip} {chin}"
        );
    }
}
