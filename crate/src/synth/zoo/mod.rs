//! The scanner zoo: what real scanners deliver besides the clean CAESAR-like scan of
//! [`super::scanner`] — the body in separate parts, the crown or the feet cut off by the field of
//! view, floor and turntable remnants, horizontal-slice sampling, photogrammetry-like blobs,
//! decimated and dense exports, stray points — and what people bring to the scanner: arms
//! against the body, an arm raised, hair, tight clothing. A [`ScannerClass`] names one; its settings, with
//! their defaults, are [`ZooParams`]. Everything is made in the template frame (metres, y up,
//! feet on y = 0) before the output frame is applied, so every class comes in every frame and
//! unit like the clean scan.
//!
//! A class may set the pose ([`ScannerClass::pose`]) and cover the body with what the scanner
//! sees instead of the skin ([`ScannerClass::cover`]); it changes the scanner's settings
//! ([`ScannerClass::scanner`]) and then edits the scan ([`ScannerClass::finish`]), all with its
//! own random stream ([`zoo_rng`], drawn in that order), so the subject's shape (and, unless the
//! class sets it, its pose) is that of the clean class for the same seed and index. The truth
//! (landmarks, template vertices) is always the body's.
//!
//! * [`edit`] — keeping vertices, adding geometry that is not the body;
//! * [`parts`] — the body split into parts;
//! * [`cleanup`] — the field of view's cuts, decimation, stray points;
//! * [`floor`] — floor patches and a turntable;
//! * [`blob`] — the photogrammetry-like closed, smooth, bumpy surface;
//! * [`poses`] — arms against the body, one arm raised;
//! * [`hair`] — a cap of hair over the skull;
//! * [`clothing`] — a tight layer shrink-wrapped over the torso and legs.

pub mod blob;
pub mod cleanup;
pub mod clothing;
pub mod edit;
pub mod floor;
pub mod hair;
pub mod parts;
pub mod poses;

use rand::Rng;
use rand_chacha::ChaCha8Rng;

use self::blob::{blob_scan, BlobParams};
use self::clothing::{shrink_wrap, ClothingParams};
use self::hair::{add_hair, Hair, HeadFrame};
use super::data::MakeHumanData;
use super::error::SynthError;
use super::population::SubjectParams;
use super::random_stream::subject_rng;
use super::scanner::{Scan, ScannerParams};
use super::subject::Subject;
use crate::mesh::Mesh;
use crate::template::{Segment, Template};

/// A kind of scanner output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum ScannerClass {
    /// The profile's CAESAR-like scanner as it is.
    Clean,
    /// Six parts: head split at the neck, torso, two arms split at the armpits, two legs split at
    /// the crotch (separate components, one mesh).
    Parts,
    /// The crown cut off by the field of view.
    CrownCut,
    /// The feet cut off by the field of view.
    FeetCut,
    /// Floor remnants: patches of the floor's plane around the feet.
    Floor,
    /// A turntable: a disc under the feet with its rim.
    Turntable,
    /// A laser-line scanner: rings of points at a coarse vertical step, dense along each ring.
    Slices,
    /// Photogrammetry-like: closed, smooth, noisy, low-frequency bumps, its own triangulation.
    Blob,
    /// A decimated export of about `ZooParams::decimated_vertices` vertices.
    Decimated,
    /// A dense export (the scanner's step `ZooParams::dense_step`: ≈ 1 million vertices).
    Dense,
    /// Stray points and small floating blobs around the body.
    Stray,
    /// A raw scanner file as issue 31 met it: five parts (torso with the head), slices, the
    /// crown cut, floor remnants.
    Raw,
    /// Both arms hanging straight against the body: the upper arm's skin meets the torso's.
    ArmsTouching,
    /// One arm raised `ZooParams::raised_arm` from the body, the other hanging.
    ArmRaised,
    /// Hair over the skull (`ZooParams::hair_top`, `hair_side`): the scanner sees the hair.
    Hair,
    /// Tight clothing over the torso and legs (`ZooParams::clothing`), shrink-wrapped: bare
    /// where the head's segment weight reaches ½, hemmed above the ankles.
    TightClothing,
}

impl ScannerClass {
    /// Every class, in the order `--zoo` cycles them.
    pub const ALL: [ScannerClass; 16] = [
        ScannerClass::Clean,
        ScannerClass::Parts,
        ScannerClass::CrownCut,
        ScannerClass::FeetCut,
        ScannerClass::Floor,
        ScannerClass::Turntable,
        ScannerClass::Slices,
        ScannerClass::Blob,
        ScannerClass::Decimated,
        ScannerClass::Dense,
        ScannerClass::Stray,
        ScannerClass::Raw,
        ScannerClass::ArmsTouching,
        ScannerClass::ArmRaised,
        ScannerClass::Hair,
        ScannerClass::TightClothing,
    ];

    /// The command-line name (`crown-cut`, …).
    pub fn name(self) -> &'static str {
        match self {
            ScannerClass::Clean => "clean",
            ScannerClass::Parts => "parts",
            ScannerClass::CrownCut => "crown-cut",
            ScannerClass::FeetCut => "feet-cut",
            ScannerClass::Floor => "floor",
            ScannerClass::Turntable => "turntable",
            ScannerClass::Slices => "slices",
            ScannerClass::Blob => "blob",
            ScannerClass::Decimated => "decimated",
            ScannerClass::Dense => "dense",
            ScannerClass::Stray => "stray",
            ScannerClass::Raw => "raw",
            ScannerClass::ArmsTouching => "arms-touching",
            ScannerClass::ArmRaised => "arm-raised",
            ScannerClass::Hair => "hair",
            ScannerClass::TightClothing => "tight-clothing",
        }
    }

    /// The class named `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.name() == name)
    }

    /// The subject this class scans: `params` (drawn by the profile) with the class's pose, if
    /// it sets one.
    pub fn pose<R: Rng>(
        self,
        data: &MakeHumanData,
        params: &SubjectParams,
        zoo: &ZooParams,
        rng: &mut R,
    ) -> Result<SubjectParams, SynthError> {
        match self {
            ScannerClass::ArmsTouching => poses::arms_touching(data, params, zoo.arm_press),
            ScannerClass::ArmRaised => Ok(poses::one_arm_raised(
                params,
                zoo.raised_arm,
                zoo.lowered_arm,
                rng,
            )),
            _ => Ok(params.clone()),
        }
    }

    /// What the scanner sees of the posed body `surface` (template vertices; `template` gives
    /// their segments and landmarks), when it is not the skin: the hair's or the clothing's
    /// surface on the same triangles. `None` for the skin itself (and when the template lacks the
    /// landmarks the hair is placed by).
    pub fn cover<R: Rng>(
        self,
        surface: &Mesh,
        template: &Template,
        zoo: &ZooParams,
        rng: &mut R,
    ) -> Option<Mesh> {
        let weights = template.segment_weight_table();
        let weight = |v: usize, s: Segment| weights.get(v).map_or(0.0, |w| w[s.index()] as f64);
        let at = |name: &str| {
            let v = template.landmark_vertex(name)? as usize;
            surface.positions.get(v).copied()
        };
        let n = surface.positions.len();
        match self {
            ScannerClass::Hair => {
                let hair = Hair {
                    top: rng.gen_range(zoo.hair_top.0..=zoo.hair_top.1),
                    side: rng.gen_range(zoo.hair_side.0..=zoo.hair_side.1),
                };
                let head: Vec<f64> = (0..n).map(|v| weight(v, Segment::Head)).collect();
                let (left, right, sellion) =
                    (at("Lt. Tragion")?, at("Rt. Tragion")?, at("Sellion")?);
                let centre = nalgebra::center(&left, &right);
                let top = (0..n)
                    .filter(|&v| head[v] > 0.5)
                    .map(|v| surface.positions[v])
                    .max_by(|a, b| (a.y - centre.y).total_cmp(&(b.y - centre.y)))?;
                let frame = HeadFrame::from_points(left, right, sellion, top);
                Some(add_hair(surface, &frame, &hair, &head))
            }
            ScannerClass::TightClothing => {
                let c = &zoo.clothing;
                let thickness = rng.gen_range(c.thickness.0..=c.thickness.1);
                // The legs are covered down to a hem above the ankles.
                let ankle = at("Lt. Lateral Malleolus")?
                    .y
                    .max(at("Rt. Lateral Malleolus")?.y);
                let cover: Vec<f64> = (0..n)
                    .map(|v| {
                        let clothed = weight(v, Segment::Torso)
                            + weight(v, Segment::LeftLeg)
                            + weight(v, Segment::RightLeg);
                        // The neckline: bare where the head's weight reaches ½.
                        let neck = (1.0 - 2.0 * weight(v, Segment::Head)).clamp(0.0, 1.0);
                        let hem =
                            ((surface.positions[v].y - ankle) / c.hem_above_ankle).clamp(0.0, 1.0);
                        clothed.clamp(0.0, 1.0) * neck * hem
                    })
                    .collect();
                Some(shrink_wrap(surface, &cover, thickness, c))
            }
            _ => None,
        }
    }

    /// The scanner this class scans with, from the profile's `base`.
    pub fn scanner(self, base: &ScannerParams, zoo: &ZooParams) -> ScannerParams {
        match self {
            ScannerClass::Slices | ScannerClass::Raw => ScannerParams {
                vertical_step: zoo.slice_step,
                horizontal_step: zoo.slice_ring_step,
                max_edge_steps: zoo.slice_edge_steps,
                ..*base
            },
            ScannerClass::Dense => ScannerParams {
                vertical_step: zoo.dense_step,
                horizontal_step: zoo.dense_step,
                ..*base
            },
            _ => *base,
        }
    }

    /// The scan this class delivers of `subject` (template frame; `template` gives the body's
    /// segments for the parts), scanned by [`Self::scanner`]; draws from `rng`.
    pub fn finish<R: Rng>(
        self,
        subject: &Subject,
        template: &Template,
        scanner: &ScannerParams,
        zoo: &ZooParams,
        rng: &mut R,
    ) -> Scan {
        let scan = &subject.scan;
        let top = || {
            subject
                .surface
                .positions
                .iter()
                .map(|p| p.y)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let draw = |rng: &mut R, (lo, hi): (f64, f64)| rng.gen_range(lo..=hi);
        let step = scanner.vertical_step.max(scanner.horizontal_step);
        match self {
            ScannerClass::Clean
            | ScannerClass::Slices
            | ScannerClass::Dense
            | ScannerClass::ArmsTouching
            | ScannerClass::ArmRaised
            | ScannerClass::Hair
            | ScannerClass::TightClothing => scan.clone(),
            ScannerClass::Parts => split(subject, template, true, zoo.parts_gap),
            ScannerClass::CrownCut => cleanup::cut_field_of_view(
                scan,
                f64::NEG_INFINITY,
                top() - draw(rng, zoo.crown_cut),
            ),
            ScannerClass::FeetCut => {
                cleanup::cut_field_of_view(scan, draw(rng, zoo.feet_cut), f64::INFINITY)
            }
            ScannerClass::Floor => {
                let mut s = scan.clone();
                let margin = draw(rng, zoo.floor_margin);
                floor::add_floor(&mut s, margin, step, scanner.noise_sigma, rng);
                s
            }
            ScannerClass::Turntable => {
                let mut s = scan.clone();
                let (radius, rim) = (zoo.turntable_radius, zoo.turntable_rim);
                floor::add_turntable(&mut s, radius, rim, step, scanner.noise_sigma, rng);
                s
            }
            ScannerClass::Blob => blob_scan(&subject.surface, &zoo.blob, rng),
            ScannerClass::Decimated => {
                cleanup::decimate(scan, cleanup::cell_for(scan, zoo.decimated_vertices))
            }
            ScannerClass::Stray => {
                let mut s = scan.clone();
                let (points, clusters) = (zoo.stray_points, zoo.stray_clusters);
                cleanup::add_strays(&mut s, points, clusters, zoo.stray_margin, rng);
                s
            }
            ScannerClass::Raw => {
                let parts = split(subject, template, false, zoo.parts_gap);
                let cut = top() - draw(rng, zoo.crown_cut);
                let mut s = cleanup::cut_field_of_view(&parts, f64::NEG_INFINITY, cut);
                let margin = draw(rng, zoo.floor_margin);
                floor::add_floor(&mut s, margin, step, scanner.noise_sigma, rng);
                s
            }
        }
    }
}

/// The subject's scan split into the template's segments (the dominant segment of the body
/// vertex nearest each scan vertex); the head kept with the torso unless `neck`.
fn split(subject: &Subject, template: &Template, neck: bool, gap: f64) -> Scan {
    let weights = template.segment_weight_table();
    let labels: Vec<u8> = (0..subject.surface.positions.len())
        .map(|v| {
            let w = weights.get(v).copied().unwrap_or_default();
            let k = (0..6).max_by(|&a, &b| w[a].total_cmp(&w[b])).unwrap_or(0);
            if !neck && Segment::ALL[k] == Segment::Head {
                Segment::Torso.index() as u8
            } else {
                k as u8
            }
        })
        .collect();
    let part = parts::scan_labels(&subject.scan, &subject.surface.positions, &labels);
    parts::split_parts(&subject.scan, &part, gap)
}

/// The random stream of the zoo's edits of subject `index` under `seed`: another stream than
/// the subject's own ([`subject_rng`] of `seed` with every bit flipped).
pub fn zoo_rng(seed: u64, index: u64) -> ChaCha8Rng {
    subject_rng(!seed, index)
}

/// The zoo's settings (metres unless said otherwise); ranges `(lo, hi)` are drawn uniformly per
/// subject.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ZooParams {
    /// Parts: no vertex within this distance of another part's.
    pub parts_gap: f64,
    /// Crown cut: this far below the top of the head.
    pub crown_cut: (f64, f64),
    /// Feet cut: everything below this height.
    pub feet_cut: (f64, f64),
    /// Floor remnants: this far around the feet.
    pub floor_margin: (f64, f64),
    /// Turntable: the disc's radius and the rim's height.
    pub turntable_radius: f64,
    pub turntable_rim: f64,
    /// Slices: the vertical step between rings, the step along a ring, and the triangulation's
    /// longest edge in steps (of the vertical step).
    pub slice_step: f64,
    pub slice_ring_step: f64,
    pub slice_edge_steps: f64,
    /// Photogrammetry-like blob.
    pub blob: BlobParams,
    /// Decimated export: about this many vertices.
    pub decimated_vertices: usize,
    /// Dense export: the scanner's step.
    pub dense_step: f64,
    /// Stray points: lone points, small floating blobs, and how far around the body.
    pub stray_points: usize,
    pub stray_clusters: usize,
    pub stray_margin: f64,
    /// Arms touching: how deep the arm's skin is pressed into the torso's at the deepest.
    pub arm_press: f64,
    /// One arm raised: the raised arm's and the hanging arm's angles from the body (degrees).
    pub raised_arm: (f64, f64),
    pub lowered_arm: (f64, f64),
    /// Hair: its thickness at the top and the back, and at the sides.
    pub hair_top: (f64, f64),
    pub hair_side: (f64, f64),
    /// Tight clothing.
    pub clothing: ClothingParams,
}

impl Default for ZooParams {
    /// Parts 6 mm apart; the crown cut 2–6 cm below the top, the feet below 2–6 cm; floor 4–12 cm
    /// around the feet; a turntable of 45 cm radius with a 3 cm rim; slices every 8 mm with
    /// 1.5 mm along the ring (a laser-line scanner's 55–90 thousand vertices); a blob on a 5 mm
    /// grid blurred 1.2 voxels, 40 bumps of 5–15 cm and ±3 mm, 0.7 mm noise; decimated to about
    /// 10,000 vertices; dense at 1.25 mm (≈ 0.8–1.2 million); 300 stray points and 30 blobs
    /// within 40 cm of the body's box; arms pressed 15 mm into the torso (both soft tissues); one arm raised 90–150°,
    /// the other hanging 8–15° from the body; hair 2–4 cm thick at the top and back, 0.5–1.2 cm
    /// at the sides; clothing 1–3 mm thick bridging hollows up to 2 cm deep (at most 400 sweeps, the
    /// normals smoothed over 10 rings),
    /// its hem 3 cm above the higher lateral malleolus.
    fn default() -> Self {
        Self {
            parts_gap: 0.006,
            crown_cut: (0.02, 0.06),
            feet_cut: (0.02, 0.06),
            floor_margin: (0.04, 0.12),
            turntable_radius: 0.45,
            turntable_rim: 0.03,
            slice_step: 0.008,
            slice_ring_step: 0.0015,
            slice_edge_steps: 2.5,
            blob: BlobParams {
                voxel: 0.005,
                blur: 1.2,
                bumps: 40,
                bump_radius: (0.05, 0.15),
                bump_height: 0.003,
                sigma: 0.0007,
            },
            decimated_vertices: 10_000,
            dense_step: 0.00125,
            stray_points: 300,
            stray_clusters: 30,
            stray_margin: 0.4,
            arm_press: 0.015,
            raised_arm: (90.0, 150.0),
            lowered_arm: (8.0, 15.0),
            hair_top: (0.02, 0.04),
            hair_side: (0.005, 0.012),
            clothing: ClothingParams {
                thickness: (0.001, 0.003),
                max_bridge: 0.02,
                sweeps: 400,
                normal_smoothing: 10,
                hem_above_ankle: 0.03,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_round_trip_by_name() {
        for c in ScannerClass::ALL {
            assert_eq!(ScannerClass::from_name(c.name()), Some(c));
        }
        assert_eq!(ScannerClass::from_name("lidar"), None);
    }

    #[test]
    fn slices_and_dense_change_the_scanner_and_nothing_else() {
        let (base, zoo) = (ScannerParams::default(), ZooParams::default());
        let slices = ScannerClass::Slices.scanner(&base, &zoo);
        assert_eq!(slices.vertical_step, zoo.slice_step);
        assert!(slices.horizontal_step < slices.vertical_step / 4.0);
        assert_eq!(slices.noise_sigma, base.noise_sigma);
        assert_eq!(
            ScannerClass::Dense.scanner(&base, &zoo).vertical_step,
            zoo.dense_step
        );
        assert_eq!(ScannerClass::Parts.scanner(&base, &zoo), base);
    }
}
