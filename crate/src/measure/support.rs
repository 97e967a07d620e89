//! Whether the scan is under a fit where a body-defined measurement is taken: the fit's
//! *support* (docs/measurements.md, "Trust").
//!
//! A body-defined measurement ([`Anchoring::Surface`]) is found on the fit's surface, so it is
//! the scan's only where the fit lies on the scan. Where the scanner saw nothing (the armpits'
//! vault, the crotch, a crown cut by the field of view) or the fit did not reach the scan, the
//! fit is the template's extrapolation and the value with it. The place of each ([`place`]):
//!
//! * stature: the crown, every fit vertex within [`SupportParams::radius_mm`] of the highest
//!   level;
//! * crotch height: the fit's vertices within the radius of the fit's Crotch landmark;
//! * a girth: the vertices within the radius of its tape's corners (the convex hull's corners,
//!   [`BodyMeasurer::tape_paths`]: where the tape touches the body), and for the thigh, whose
//!   level is the crotch's, the crotch's too;
//! * and for the heights (stature, crotch height), the soles, their other end: every vertex
//!   within the radius of the lowest level.
//!
//! Its support: of those `n` vertices, the `k` whose distance to the scan (the alignment's
//! per-vertex distance, [`crate::align::Alignment::per_vertex_distance`]) exceeds
//! [`SupportParams::far_mm`] ([`SupportParams::sole_far_mm`] at the soles); the measurement is
//! unsupported when k/n exceeds [`SupportParams::max_unsupported_share`] at its place or at the
//! soles.

use serde::Serialize;

use super::body::BodyMeasurer;
use super::definitions::{Anchoring, Measure};
use super::vec3::sub;

/// Where a fit is judged near enough to the scan to carry a body-defined measurement, with the
/// defaults chosen on the tuning seeds 2026, 101 and 202 (docs/measurements.md, "Trust").
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SupportParams {
    /// Fit vertices within this of the measurement's place are judged (mm); default 15 mm,
    /// about two edges of the base template (≈ 5 vertices at the crotch, 20 at the crown, 30–150
    /// along a tape).
    pub radius_mm: f64,
    /// A vertex farther than this from the scan is unsupported (mm); default 5 mm, five times
    /// the synthetic scanner's noise and about five times a good fit's RMS.
    pub far_mm: f64,
    /// The same at the soles (mm), which a scanner never sees under a standing body, so that the
    /// template's sole spans the scan's foot: 37–59 % of the soles' vertices are beyond 5 mm on
    /// every tuning fit, ≤ 8 % beyond 20 mm (at most 33 mm away); default 20 mm.
    pub sole_far_mm: f64,
    /// The measurement is doubtful when more than this share of its vertices is unsupported;
    /// default 0.5: more than half of the place is the template's. Every synthetic scan has a
    /// small hole at the crown (10–43 % of the crown's vertices beyond 5 mm, up to 26 mm away)
    /// and stature within 4.2 mm all the same; at 0.5 the crown is never doubtful there, and the
    /// crotch is on 12 of 48 fits, 8 of them over the limit (at 0.3: 28, 13 over).
    pub max_unsupported_share: f64,
}

impl Default for SupportParams {
    fn default() -> Self {
        Self {
            radius_mm: 15.0,
            far_mm: 5.0,
            sole_far_mm: 20.0,
            max_unsupported_share: 0.5,
        }
    }
}

/// Where a body-defined measurement is taken on a fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// The highest level of the body.
    Crown,
    /// Around one landmark of the fit.
    Landmark(&'static str),
    /// Around the tape's corners.
    Tape,
    /// Around the tape's corners and one landmark (a girth whose level a landmark's place
    /// fixes).
    TapeAnd(&'static str),
}

/// The place of `m`, for a body-defined measurement with an ISO 20685-1 limit; `None` for the
/// others (landmark-defined ones are judged by their landmarks' origin, volume and area have no
/// limit).
pub fn place(m: Measure) -> Option<Place> {
    if m.definition().anchoring != Anchoring::Surface || m.iso_class().is_none() {
        return None;
    }
    Some(match m {
        Measure::Stature => Place::Crown,
        Measure::CervicaleHeight => Place::Landmark("Cervicale"),
        Measure::CrotchHeight => Place::Landmark("Crotch"),
        Measure::ThighGirth => Place::TapeAnd("Crotch"),
        _ => Place::Tape,
    })
}

/// Whether `m` is a height above the floor, so that the soles are its other end.
fn above_the_soles(m: Measure) -> bool {
    matches!(
        m,
        Measure::Stature | Measure::CervicaleHeight | Measure::CrotchHeight
    )
}

/// Which part of a measurement's place a [`Support`] judged.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum At {
    /// The measurement's own [`place`].
    Place,
    /// The soles, a height's other end.
    Soles,
}

/// The fit's support where one measurement is taken.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Support {
    /// The part judged: its place, or the soles when they failed and the place did not.
    pub at: At,
    /// Fit vertices there.
    pub vertices: usize,
    /// Of them, those farther than [`SupportParams::far_mm`] (at the soles
    /// [`SupportParams::sole_far_mm`]) from the scan.
    pub unsupported: usize,
    /// unsupported / vertices (0 when there are none).
    pub unsupported_share: f64,
    /// The largest distance to the scan among them (mm).
    pub max_distance_mm: f64,
    /// The share above [`SupportParams::max_unsupported_share`].
    pub doubtful: bool,
}

/// Each measurement's support on a fit, in [`Measure::ALL`] order (`None` where [`place`] is).
/// `upright`: the fit's `#V·3` positions (metres) standing in the measurer's frame, up along
/// `up`; `distances`: each vertex's distance to the scan (metres, signed or not; at least `#V`);
/// `landmarks`: the template's (canonical name, vertex) list.
pub fn measurements_support(
    measurer: &BodyMeasurer,
    landmarks: &[(String, u32)],
    upright: &[f32],
    up: usize,
    distances: &[f64],
    params: &SupportParams,
) -> Vec<Option<Support>> {
    let radius = params.radius_mm * 1e-3;
    let soles = level(upright, up, radius, false);
    let soles = support(At::Soles, &soles, distances, params);
    places(measurer, landmarks, upright, up, radius)
        .into_iter()
        .zip(Measure::ALL)
        .map(|(vertices, m)| {
            let s = support(At::Place, &vertices?, distances, params);
            Some(match !s.doubtful && soles.doubtful && above_the_soles(m) {
                true => soles.clone(),
                false => s,
            })
        })
        .collect()
}

/// The fit's vertices within `radius` (metres) of its highest level (`top`) or its lowest.
fn level(upright: &[f32], up: usize, radius: f64, top: bool) -> Vec<usize> {
    let height = |v: usize| upright[3 * v + up] as f64;
    let n = upright.len() / 3;
    let sign = if top { 1.0 } else { -1.0 };
    let extreme = (0..n).map(|v| sign * height(v)).fold(f64::MIN, f64::max);
    (0..n)
        .filter(|&v| sign * height(v) >= extreme - radius)
        .collect()
}

/// The fit's vertices at each measurement's [`place`], in [`Measure::ALL`] order: within
/// `radius` (metres) of its tape's corners or landmark, or of the highest level.
pub fn places(
    measurer: &BodyMeasurer,
    landmarks: &[(String, u32)],
    upright: &[f32],
    up: usize,
    radius: f64,
) -> Vec<Option<Vec<usize>>> {
    let tapes = measurer.tape_paths(upright).unwrap_or_default();
    let vertex = |v: usize| {
        let p = &upright[3 * v..3 * v + 3];
        [p[0] as f64, p[1] as f64, p[2] as f64]
    };
    let n = upright.len() / 3;
    let near = |centres: &[[f64; 3]]| -> Vec<usize> {
        // A vertex outside the centres' box widened by twice the radius lies, along one axis
        // alone, more than twice the radius from every centre: farther than the radius from each
        // whatever the rounding, so it is skipped unmeasured.
        let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for c in centres {
            for k in 0..3 {
                low[k] = low[k].min(c[k] - 2.0 * radius);
                high[k] = high[k].max(c[k] + 2.0 * radius);
            }
        }
        (0..n)
            .filter(|&v| {
                let p = vertex(v);
                (0..3).all(|k| low[k] <= p[k] && p[k] <= high[k])
                    && centres.iter().any(|c| {
                        let d = sub(p, *c);
                        d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= radius * radius
                    })
            })
            .collect()
    };
    let landmark = |name: &str| {
        landmarks
            .iter()
            .find(|(n, _)| n == name)
            .map(|&(_, v)| v as usize)
            .filter(|&v| v < n)
            .map(vertex)
    };
    let tape = |m: Measure| {
        tapes
            .iter()
            .find(|t| t.measure == m)
            .map(|t| t.points.clone())
            .unwrap_or_default()
    };
    Measure::ALL
        .into_iter()
        .map(|m| {
            Some(match place(m)? {
                Place::Crown => level(upright, up, radius, true),
                Place::Landmark(name) => near(&landmark(name).into_iter().collect::<Vec<_>>()),
                Place::Tape => near(&tape(m)),
                Place::TapeAnd(name) => {
                    let mut centres = tape(m);
                    centres.extend(landmark(name));
                    near(&centres)
                }
            })
        })
        .collect()
}

/// The support of `vertices` (the part `at` of a place) given each vertex's `distances` to the
/// scan (metres).
pub fn support(at: At, vertices: &[usize], distances: &[f64], params: &SupportParams) -> Support {
    let far = far_mm(at, params) * 1e-3;
    let d: Vec<f64> = vertices
        .iter()
        .map(|&v| distances.get(v).map_or(f64::INFINITY, |d| d.abs()))
        .collect();
    let unsupported = d.iter().filter(|&&d| d.is_nan() || d > far).count();
    let unsupported_share = if d.is_empty() {
        0.0
    } else {
        unsupported as f64 / d.len() as f64
    };
    Support {
        at,
        vertices: d.len(),
        unsupported,
        unsupported_share,
        max_distance_mm: d.iter().fold(0.0, |a: f64, &b| a.max(b)) * 1e3,
        doubtful: unsupported_share > params.max_unsupported_share,
    }
}

fn far_mm(at: At, params: &SupportParams) -> f64 {
    match at {
        At::Place => params.far_mm,
        At::Soles => params.sole_far_mm,
    }
}

/// What a person reads of an unsupported measurement: "chest girth: the scan has no surface
/// within 5 mm of 38 % of the fit where its tape runs (up to 24 mm away): the fit there is the
/// template's, not the scan's".
pub fn words(m: Measure, s: &Support, params: &SupportParams) -> String {
    let d = m.definition();
    let at = match (s.at, place(m)) {
        (At::Soles, _) => "at the soles (its feet are not on the scan's)",
        (_, Some(Place::Crown)) => "at the crown (a scanner's field of view often cuts it)",
        (_, Some(Place::Landmark(_))) => {
            "at the crotch (between the legs, where a scanner sees little)"
        }
        (_, Some(Place::TapeAnd(_))) => "where its tape runs and at the crotch",
        _ => "where its tape runs",
    };
    format!(
        "{}: the scan has no surface within {:.0} mm of {:.0} % of the fit {at} (up to {:.0} mm \
         away): the fit there is the template's, not the scan's",
        d.label.to_lowercase(),
        far_mm(s.at, params),
        100.0 * s.unsupported_share,
        s.max_distance_mm
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measure::MeasureParams;
    use crate::template::Template;

    /// The template itself as the fit, each vertex `far(v)` metres from a scan.
    fn judged(far: &dyn Fn([f64; 3], f64) -> f64) -> (Vec<Option<Support>>, Template) {
        let template = Template::embedded().unwrap();
        let params = MeasureParams::default();
        let measurer = BodyMeasurer::of_template(&template, params).unwrap();
        let positions = &template.mesh().positions;
        let stood: Vec<f32> = positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let top = positions.iter().map(|p| p.y).fold(f64::MIN, f64::max);
        let distances: Vec<f64> = positions
            .iter()
            .map(|p| far([p.x, p.y, p.z], top))
            .collect();
        let supports = measurements_support(
            &measurer,
            template.landmark_vertices(),
            &stood,
            params.up_axis,
            &distances,
            &SupportParams::default(),
        );
        (supports, template)
    }

    #[test]
    fn a_fit_on_the_scan_supports_every_body_defined_measurement() {
        let (supports, _) = judged(&|_, _| 0.001);
        for m in Measure::ALL {
            let s = &supports[m.index()];
            assert_eq!(s.is_some(), place(m).is_some(), "{m:?}");
            if let Some(s) = s {
                assert!(
                    s.vertices > 0 && s.unsupported == 0 && !s.doubtful,
                    "{m:?}: {s:?}"
                );
                assert!((s.max_distance_mm - 1.0).abs() < 1e-9);
            }
        }
        assert_eq!(place(Measure::ShoulderBreadth), None);
        assert_eq!(place(Measure::Volume), None);
    }

    #[test]
    fn a_cut_crown_leaves_stature_alone_unsupported() {
        // The scan ends 30 mm under the crown: the fit above it is 30 mm off at the top.
        let (supports, _) = judged(&|p, top| (p[1] - (top - 0.03)).max(0.001));
        let stature = supports[Measure::Stature.index()].as_ref().unwrap();
        assert!(stature.doubtful, "{stature:?}");
        assert_eq!(stature.unsupported_share, 1.0);
        assert!((stature.max_distance_mm - 30.0).abs() < 1e-6);
        for m in [
            Measure::ChestGirth,
            Measure::HipGirth,
            Measure::CrotchHeight,
        ] {
            assert!(!supports[m.index()].as_ref().unwrap().doubtful, "{m:?}");
        }
        let words = words(Measure::Stature, stature, &SupportParams::default());
        assert_eq!(
            words,
            "stature: the scan has no surface within 5 mm of 100 % of the fit at the crown (a \
             scanner's field of view often cuts it) (up to 30 mm away): the fit there is the \
             template's, not the scan's"
        );
    }

    #[test]
    fn feet_off_the_scan_leave_both_heights_unsupported() {
        // The fit's feet reach 30 mm below the scan's: the soles are 30 mm off, the rest on it.
        let floor = Template::embedded()
            .unwrap()
            .mesh()
            .positions
            .iter()
            .map(|p| p.y)
            .fold(f64::MAX, f64::min);
        let (supports, _) = judged(&|p, _| if p[1] < floor + 0.03 { 0.03 } else { 0.001 });
        for m in [Measure::Stature, Measure::CrotchHeight] {
            let s = supports[m.index()].as_ref().unwrap();
            assert!(s.doubtful && s.at == At::Soles, "{m:?}: {s:?}");
        }
        assert!(
            !supports[Measure::HipGirth.index()]
                .as_ref()
                .unwrap()
                .doubtful
        );
        let s = supports[Measure::Stature.index()].as_ref().unwrap();
        assert!(
            words(Measure::Stature, s, &SupportParams::default()).starts_with(
                "stature: the scan has no surface within 20 mm of 100 % of the fit at the soles"
            )
        );
    }

    #[test]
    fn a_fit_far_from_the_scan_around_one_girth_makes_that_girth_doubtful() {
        // Every vertex within 40 mm of the hip girth's tape level is 12 mm off the scan.
        let template = Template::embedded().unwrap();
        let measurer = BodyMeasurer::of_template(&template, MeasureParams::default()).unwrap();
        let stood: Vec<f32> = template
            .mesh()
            .positions
            .iter()
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect();
        let tapes = measurer.tape_paths(&stood).unwrap();
        let hip = tapes
            .iter()
            .find(|t| t.measure == Measure::HipGirth)
            .unwrap();
        let level = hip.points[0][1];
        let (supports, _) = judged(&|p, _| {
            if (p[1] - level).abs() < 0.04 {
                0.012
            } else {
                0.001
            }
        });
        let s = supports[Measure::HipGirth.index()].as_ref().unwrap();
        assert!(s.doubtful && s.unsupported_share == 1.0, "{s:?}");
        for m in [Measure::Stature, Measure::NeckGirth, Measure::ChestGirth] {
            assert!(!supports[m.index()].as_ref().unwrap().doubtful, "{m:?}");
        }
        // Half of the place off, and no more, stays trusted: the share must exceed 0.5.
        let half = support(
            At::Place,
            &[0, 1],
            &[0.001, 0.012],
            &SupportParams::default(),
        );
        assert_eq!(half.unsupported_share, 0.5);
        assert!(!half.doubtful);
        let none = support(At::Place, &[], &[], &SupportParams::default());
        assert!(!none.doubtful && none.vertices == 0);
    }
}
