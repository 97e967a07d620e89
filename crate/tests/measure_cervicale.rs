//! The cervicale found on the back profile (docs/measurements.md, "The cervicale on the back of
//! the neck"): on a torso and neck of revolution whose back turns into the neck along a known
//! curve, the level is found within a millimetre from guesses 2 cm under or over it; on the
//! template, the default fraction is where its own Cervicale vertex stands, and moving the
//! Cervicale landmark 2 cm along the back moves cervicale height at most 2 mm.

use bodyspace::measure::cervicale::back_profile;
use bodyspace::measure::{BodyMeasurer, Measure, MeasureParams};
use bodyspace::template::Template;
use std::f64::consts::PI;

mod measure_support;
use measure_support::ring_surface;

const STEP: f64 = 0.002;
const BOTTOM: f64 = 1.10;
const RINGS: usize = 301;
const AROUND: usize = 96;
/// The back's radius: BACK up to the upper back's peak at PEAK, then down a half cosine to the
/// neck's NECK at TROUGH, then out again to the head's.
const BACK: f64 = 0.12;
const PEAK: f64 = 1.30;
const NECK: f64 = 0.055;
const TROUGH: f64 = 1.48;

fn height(i: usize) -> f64 {
    BOTTOM + STEP * i as f64
}

/// The back's radius at height y (the front's is a constant 0.09: only the back is sought).
fn back(y: f64) -> f64 {
    if y <= PEAK {
        BACK
    } else if y <= TROUGH {
        let t = (y - PEAK) / (TROUGH - PEAK);
        NECK + (BACK - NECK) * (1.0 + (PI * t).cos()) / 2.0
    } else {
        NECK + 0.3 * (y - TROUGH).powi(2)
    }
}

/// The torso and neck: rings of half-ellipses, +z the back.
fn body() -> (Vec<f32>, Vec<[u32; 3]>) {
    ring_surface(
        RINGS,
        AROUND,
        |i, t| {
            let y = height(i);
            let z = if t.sin() > 0.0 { back(y) } else { 0.09 };
            [0.14 * t.cos(), y, z * t.sin()]
        },
        [0.0, BOTTOM, 0.0],
        [0.0, height(RINGS - 1), 0.0],
    )
}

/// Where the known profile has come the fraction `f` of the way from the peak to the trough.
fn known_level(f: f64) -> f64 {
    // back(y) = NECK + (BACK − NECK)(1 + cos πt)/2 = BACK − f (BACK − NECK)  ⇔  cos πt = 1 − 2f.
    PEAK + (TROUGH - PEAK) * (1.0 - 2.0 * f).acos() / PI
}

#[test]
fn the_cervicale_is_where_the_back_has_turned_into_the_neck_wherever_the_guess_is() {
    let (p, t) = body();
    let all: Vec<u32> = (0..t.len() as u32).collect();
    let params = MeasureParams::default();
    let f = params.cervicale_fraction;
    let want = known_level(f);
    for moved in [-0.02, 0.0, 0.02] {
        let guess = want + moved;
        let profile = back_profile(
            &p,
            &t,
            &all,
            [0.0, guess, 0.0],
            [0.0, 0.0, 1.0],
            1,
            (
                guess - params.cervicale_band_below,
                guess + params.cervicale_band_above,
            ),
            params.cervicale_step,
        )
        .unwrap();
        let turn = profile.turn(guess).unwrap();
        let level = profile.level(&turn, f).unwrap();
        assert!(
            (level - want).abs() < 0.001,
            "guess {moved:+} m: level {level:.4} vs {want:.4}"
        );
        // The profile is the back's surface.
        let at = profile.back_at(level).unwrap();
        assert!((at - back(level)).abs() < 0.0005, "{at} vs {}", back(level));
    }
}

/// The template's vertex on its back's midline nearest `height` (the Cervicale moved there).
fn back_midline_vertex(template: &Template, height: f64) -> u32 {
    let rest = &template.mesh().positions;
    (0..rest.len())
        .filter(|&v| rest[v].x.abs() < 0.005 && rest[v].z < -0.005 && rest[v].z > -0.06)
        .min_by(|&a, &b| {
            (rest[a].y - height)
                .abs()
                .total_cmp(&(rest[b].y - height).abs())
        })
        .unwrap() as u32
}

#[test]
fn on_the_template_the_cervicale_is_its_vertex_and_moving_the_landmark_2_cm_moves_it_at_most_2_mm()
{
    let template = Template::embedded().unwrap();
    let rest = template.mesh().flat_positions_f32();
    let cervicale = template.landmark_vertex("Cervicale").unwrap();
    let vertex_height = template.mesh().positions[cervicale as usize].y;
    let measurer = |landmarks: &[(String, u32)]| {
        BodyMeasurer::new(
            &rest,
            &template.mesh().triangles,
            template.segment_weight_table(),
            landmarks,
            MeasureParams::default(),
        )
        .unwrap()
    };
    let own = measurer(template.landmark_vertices());
    // The default fraction is where the template's own Cervicale vertex stands.
    let (profile, turn) = own.back_of_neck(&rest).unwrap().unwrap();
    let fraction = profile.fraction_at(&turn, vertex_height).unwrap();
    assert!(
        (fraction - MeasureParams::default().cervicale_fraction).abs() < 0.001,
        "the template's Cervicale stands at {fraction:.4} of its back's turn"
    );
    let floor = template
        .mesh()
        .positions
        .iter()
        .map(|p| p.y)
        .fold(f64::INFINITY, f64::min);
    let height = |m: &BodyMeasurer| m.measure(&rest).unwrap().get(Measure::CervicaleHeight);
    let at_rest = height(&own).unwrap();
    assert!(
        (at_rest - (vertex_height - floor)).abs() < 0.0005,
        "{} vs the vertex's {} mm",
        at_rest * 1e3,
        (vertex_height - floor) * 1e3
    );
    for moved in [-0.02, 0.02] {
        let v = back_midline_vertex(&template, vertex_height + moved);
        let landmarks: Vec<(String, u32)> = template
            .landmark_vertices()
            .iter()
            .map(|(n, w)| (n.clone(), if n == "Cervicale" { v } else { *w }))
            .collect();
        let got = height(&measurer(&landmarks)).unwrap();
        assert!(
            (got - at_rest).abs() <= 0.002,
            "the Cervicale moved {moved:+} m: {} vs {} mm",
            got * 1e3,
            at_rest * 1e3
        );
    }
}
