//! The head's pitch: how far the line from the ears to the eyes rises above the level. The
//! Frankfurt plane runs through the ear (tragion or porion) and the lowest point of the eye
//! socket's rim (orbitale); ISO 7250-1's standing posture holds it level, and a person standing
//! to be scanned holds it near level. CAESAR marks the Tragions and the Infraorbitales, so the
//! line here runs from the Tragions' midpoint to the Infraorbitales' midpoint, and its pitch is
//! its angle above the plane square to the body's up (positive: the face turned up).

use nalgebra::{Point3, Vector3};

use super::caesar::caesar_index;

/// The pitch (degrees) of the Tragions' → Infraorbitales' line above the plane square to `up`
/// (unit), from a body's landmarks (`at`: CAESAR index → position, `None` where unknown). `None`
/// when one of the four is unknown or the line runs along `up`.
pub fn head_pitch_deg(at: &dyn Fn(usize) -> Option<Point3<f64>>, up: &Vector3<f64>) -> Option<f64> {
    let p = |name: &str| caesar_index(name).and_then(at);
    let ears = nalgebra::center(&p("Rt. Tragion")?, &p("Lt. Tragion")?);
    let eyes = nalgebra::center(&p("Rt. Infraorbitale")?, &p("Lt. Infraorbitale")?);
    let line = eyes - ears;
    let rise = line.dot(up);
    let level = (line - up * rise).norm();
    (level > 1e-12).then(|| rise.atan2(level).to_degrees())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::landmarks::CAESAR_LANDMARK_COUNT;

    /// Ears at the origin's sides, eyes 8 cm in front of them (+z) and `rise` above (+y).
    fn head(rise: f64) -> Vec<Option<Point3<f64>>> {
        let mut at = vec![None; CAESAR_LANDMARK_COUNT];
        let mut put = |name: &str, p: Point3<f64>| at[caesar_index(name).unwrap()] = Some(p);
        put("Rt. Tragion", Point3::new(-0.07, 0.0, 0.0));
        put("Lt. Tragion", Point3::new(0.07, 0.0, 0.0));
        put("Rt. Infraorbitale", Point3::new(-0.03, rise, 0.08));
        put("Lt. Infraorbitale", Point3::new(0.03, rise, 0.08));
        at
    }

    #[test]
    fn the_pitch_is_the_ear_to_eye_line_above_the_level() {
        let pitch =
            |at: &[Option<Point3<f64>>], up: Vector3<f64>| head_pitch_deg(&|k| at[k], &up).unwrap();
        assert!(pitch(&head(0.0), Vector3::y()).abs() < 1e-9);
        assert!((pitch(&head(0.08), Vector3::y()) - 45.0).abs() < 1e-9);
        assert!((pitch(&head(-0.08), Vector3::y()) + 45.0).abs() < 1e-9);
        // Up the other way: the same line falls.
        assert!((pitch(&head(0.08), -Vector3::y()) + 45.0).abs() < 1e-9);
        // An eye missing: no pitch.
        let mut missing = head(0.0);
        missing[caesar_index("Lt. Infraorbitale").unwrap()] = None;
        assert!(head_pitch_deg(&|k| missing[k], &Vector3::y()).is_none());
    }
}
