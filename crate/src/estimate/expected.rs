//! Where each given landmark is expected, to judge it (`suspicious.rs`): from the other given
//! landmarks of its rigid part (`segments.rs`) by a similarity fit (Umeyama) of the template's
//! landmarks onto them, when the part has at least [`MIN_OTHERS`] others; otherwise from the
//! segment-wise fit of the scan, which is less precise (its worst error on the synthetic
//! subjects is ≈ 9 cm, on the fingertips), so it is judged with a wider threshold.

use nalgebra::Point3;

use crate::mesh::similarity::similarity;

/// Other given landmarks a part needs for the similarity prediction.
pub const MIN_OTHERS: usize = 3;

/// Where a landmark is expected and how it was predicted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expected {
    pub position: Point3<f64>,
    /// From the other given landmarks of its part (true) or from the fit (false).
    pub from_given: bool,
}

/// The expected position of every landmark (73): `template` the template's landmark positions
/// (any frame), `part` the rigid part of each, `given` (CAESAR index, position) and `fitted` the
/// fit's prediction of all 73, both in the scan's frame and units.
pub fn expected_positions(
    template: &[Point3<f64>],
    part: &[usize],
    given: &[(usize, Point3<f64>)],
    fitted: &[Point3<f64>],
) -> Vec<Expected> {
    (0..template.len())
        .map(|i| {
            let others: Vec<&(usize, Point3<f64>)> = given
                .iter()
                .filter(|(j, _)| *j != i && part[*j] == part[i])
                .collect();
            let from: Vec<_> = others.iter().map(|(j, _)| template[*j]).collect();
            let to: Vec<_> = others.iter().map(|(_, p)| *p).collect();
            let fit = (others.len() >= MIN_OTHERS)
                .then(|| similarity(&from, &to, true))
                .flatten()
                .filter(|t| t.scale.is_finite() && t.scale > 0.0);
            match fit {
                Some(t) => Expected {
                    position: t.apply(&template[i]),
                    from_given: true,
                },
                None => Expected {
                    position: fitted[i],
                    from_given: false,
                },
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::similarity::Similarity;
    use crate::mesh::test_points::scattered;

    #[test]
    fn others_of_the_part_predict_and_a_lonely_part_falls_back_to_the_fit() {
        let template = scattered();
        let t = Similarity::from_euler_angles(1000.0, [0.1, 0.2, 0.3], [5.0, 6.0, 7.0]);
        // Four points in part 0, and point 4 given but alone in part 1.
        let part = [0, 0, 0, 0, 1];
        let given: Vec<_> = (0..5).map(|i| (i, t.apply(&template[i]))).collect();
        let fitted = vec![Point3::new(-1.0, -1.0, -1.0); 5];
        let e = expected_positions(&template, &part, &given, &fitted);
        for i in 0..4 {
            assert!(e[i].from_given);
            assert!((e[i].position - t.apply(&template[i])).norm() < 1e-6);
        }
        assert!(!e[4].from_given);
        assert_eq!(e[4].position, fitted[4]);
    }
}
