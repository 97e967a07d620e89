//! Making a numbered population: subject `i` of seed `S` from its own random stream
//! ([`super::random_stream`]), the same whatever the number of subjects or threads.

use rand_chacha::ChaCha8Rng;

use crate::landmarks::LandmarkSet;
use crate::mesh::Mesh;
use crate::template::Template;

use super::data::MakeHumanData;
use super::error::SynthError;
use super::output::{subject_landmarks, LandmarkParams, Units};
use super::population::PopulationProfile;
use super::random_stream::subject_rng;
use super::scanner::ScannerParams;
use super::subject::{make_covered_subject, make_subject, Subject};
use super::zoo::{zoo_rng, ScannerClass, ZooParams};

/// Which subject: number `index` of the population `seed` drawn from `profile`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SubjectId {
    pub profile: PopulationProfile,
    pub seed: u64,
    pub index: u64,
}

/// Subject `id`, with its landmark set in the output frame (`scanner` is usually
/// `id.profile.scanner()`).
/// Draw order on the subject's stream: shape and pose, scanner noise, landmark noise and drops.
pub fn population_subject(
    data: &MakeHumanData,
    template: &Template,
    id: SubjectId,
    scanner: &ScannerParams,
    landmarks: &LandmarkParams,
    units: Units,
) -> Result<(Subject, LandmarkSet), SynthError> {
    let mut rng = subject_rng(id.seed, id.index);
    let params = id.profile.sample_subject(&mut rng);
    let subject = make_subject(data, &params, scanner, &mut rng)?;
    let set = body_landmarks(template, &subject, landmarks, units, &mut rng);
    Ok((subject, set))
}

/// Subject `id` as scanner class `class` delivers it (`scanner` the profile's, changed by the
/// class; `zoo` the class's settings), with its landmark set in the output frame. The shape and
/// (unless the class sets it) the pose are those of [`population_subject`]; the class's pose,
/// cover and edits draw from [`zoo_rng`], in that order. The landmarks are the body's.
#[allow(clippy::too_many_arguments)]
pub fn zoo_subject(
    data: &MakeHumanData,
    template: &Template,
    id: SubjectId,
    class: ScannerClass,
    scanner: &ScannerParams,
    zoo: &ZooParams,
    landmarks: &LandmarkParams,
    units: Units,
) -> Result<(Subject, LandmarkSet), SynthError> {
    let scanner = class.scanner(scanner, zoo);
    let mut rng = subject_rng(id.seed, id.index);
    let mut zoo_draws = zoo_rng(id.seed, id.index);
    let drawn = id.profile.sample_subject(&mut rng);
    let params = class.pose(data, &drawn, zoo, &mut zoo_draws)?;
    let cover = |surface: &Mesh| class.cover(surface, template, zoo, &mut zoo_draws);
    let mut subject = make_covered_subject(data, &params, &scanner, cover, &mut rng)?;
    let set = body_landmarks(template, &subject, landmarks, units, &mut rng);
    subject.scan = class.finish(&subject, template, &scanner, zoo, &mut zoo_draws);
    Ok((subject, set))
}

/// The landmark set of `subject`'s body (its template landmark vertices, with placement noise
/// and drops from `rng`) in the output frame.
fn body_landmarks(
    template: &Template,
    subject: &Subject,
    landmarks: &LandmarkParams,
    units: Units,
    rng: &mut ChaCha8Rng,
) -> LandmarkSet {
    subject_landmarks(
        template.landmark_vertices(),
        &subject.surface.positions,
        landmarks,
        units,
        rng,
    )
}
