//! The zoo's poses: arms hanging against the body, one arm raised. A pose class keeps the
//! subject's drawn shape, trunk, head and stance and sets the arms (elbows straight); the arms
//! are posed by the generator's skeleton as every pose is (`synth::subject`).

use rand::Rng;

use crate::synth::arm_contact::arms_against_body;
use crate::synth::data::MakeHumanData;
use crate::synth::error::SynthError;
use crate::synth::population::{SubjectParams, A_POSE_ARM_DEG};

/// Both arms hanging straight, each at the shoulder abduction where its skin is pressed `press`
/// (m) into the torso's (`arm_contact::arms_against_body`): the scanner sees one merged surface
/// where the upper arm lies on the chest's side.
pub fn arms_touching(
    data: &MakeHumanData,
    params: &SubjectParams,
    press: f64,
) -> Result<SubjectParams, SynthError> {
    arms_against_body(data, params, press)
}

/// One arm (left or right with probability ½) raised `raised` degrees from the body in the
/// frontal plane (drawn uniformly), the other hanging `lowered` degrees from it, elbows straight.
/// Draws the side, then the raised angle, then the lowered one.
pub fn one_arm_raised<R: Rng>(
    params: &SubjectParams,
    raised: (f64, f64),
    lowered: (f64, f64),
    rng: &mut R,
) -> SubjectParams {
    let mut p = params.clone();
    let left = rng.gen_bool(0.5);
    let up = rng.gen_range(raised.0..=raised.1) - A_POSE_ARM_DEG;
    let down = rng.gen_range(lowered.0..=lowered.1) - A_POSE_ARM_DEG;
    let pose = &mut p.pose;
    (pose.left_shoulder_abduction, pose.right_shoulder_abduction) =
        if left { (up, down) } else { (down, up) };
    pose.left_elbow_flexion = 0.0;
    pose.right_elbow_flexion = 0.0;
    p
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::population::sample_held_out;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn one_arm_is_raised_90_to_150_degrees_and_the_other_hangs() {
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        let (mut lefts, mut rights) = (0, 0);
        for _ in 0..100 {
            let drawn = sample_held_out(&mut rng);
            let p = one_arm_raised(&drawn, (90.0, 150.0), (8.0, 15.0), &mut rng);
            let (l, r) = (
                p.pose.left_shoulder_abduction + A_POSE_ARM_DEG,
                p.pose.right_shoulder_abduction + A_POSE_ARM_DEG,
            );
            let (up, down) = if l > r { (l, r) } else { (r, l) };
            if l > r {
                lefts += 1;
            } else {
                rights += 1;
            }
            assert!((90.0..=150.0).contains(&up) && (8.0..=15.0).contains(&down));
            assert!(up - down >= 60.0);
            assert_eq!(
                (p.pose.left_elbow_flexion, p.pose.right_elbow_flexion),
                (0.0, 0.0)
            );
            assert_eq!(
                (p.shape, p.pose.trunk_turn),
                (drawn.shape, drawn.pose.trunk_turn)
            );
        }
        assert!(lefts > 30 && rights > 30, "{lefts} {rights}");
    }
}
