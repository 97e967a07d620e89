//! A small synthetic "body" for the PCA tests: a tube of rings with six overlapping segments
//! (head on top, torso, arms on the torso's sides, legs below split by x), and subjects that vary
//! it along a few known shape directions plus a random rigid pose; and checks every PCA test
//! makes of a model.

#![allow(dead_code)]

use bodyspace::pca::random::NormalRng;
use bodyspace::pca::{TemplateIdentity, TrainingSet};
use nalgebra::{Point3, Rotation3, Vector3};

pub const RINGS: usize = 24;
pub const AROUND: usize = 16;

fn ramp(t: f64, a: f64, b: f64) -> f64 {
    ((t - a) / (b - a)).clamp(0.0, 1.0)
}

pub fn template_identity() -> TemplateIdentity {
    TemplateIdentity {
        name: "test-tube".into(),
        hash: "0123abcd".into(),
        resolution: "base".into(),
        vertex_count: RINGS * AROUND,
    }
}

/// Mean tube: radius 0.15, height 1.7, y up.
pub fn tube() -> Vec<Point3<f64>> {
    let mut p = Vec::new();
    for r in 0..RINGS {
        let y = 1.7 * r as f64 / (RINGS - 1) as f64;
        for a in 0..AROUND {
            let th = std::f64::consts::TAU * a as f64 / AROUND as f64;
            p.push(Point3::new(0.15 * th.cos(), y, 0.15 * th.sin()));
        }
    }
    p
}

pub fn triangles() -> Vec<[u32; 3]> {
    let mut t = Vec::new();
    for r in 0..RINGS - 1 {
        for a in 0..AROUND {
            let i = |r: usize, a: usize| (r * AROUND + a % AROUND) as u32;
            t.push([i(r, a), i(r + 1, a), i(r + 1, a + 1)]);
            t.push([i(r, a), i(r + 1, a + 1), i(r, a + 1)]);
        }
    }
    t
}

pub fn segment_weights() -> Vec<[f32; 6]> {
    tube()
        .iter()
        .map(|p| {
            let t = p.y / 1.7;
            let head = ramp(t, 0.75, 0.85);
            let torso = ramp(t, 0.25, 0.35) * (1.0 - ramp(t, 0.75, 0.85));
            let leg = 1.0 - ramp(t, 0.25, 0.35);
            let side = ramp(t, 0.45, 0.5) * (1.0 - ramp(t, 0.7, 0.75));
            let arm_l = side * ramp(p.x, 0.05, 0.12);
            let arm_r = side * ramp(-p.x, 0.05, 0.12);
            let (leg_l, leg_r) = if p.x >= 0.0 { (leg, 0.0) } else { (0.0, leg) };
            [head, arm_l, arm_r, torso, leg_l, leg_r].map(|w| w as f32)
        })
        .collect()
}

/// Subject i: the tube scaled in height and girth, with a belly bulge and a head tilt, each
/// amount drawn from a seeded normal, then a random rigid pose.
pub fn subjects(n: usize, seed: u64) -> Vec<Vec<Point3<f64>>> {
    let mut rng = NormalRng::new(seed);
    (0..n)
        .map(|_| {
            let tall = 1.0 + 0.05 * rng.next_normal();
            let wide = 1.0 + 0.1 * rng.next_normal();
            let belly = 0.03 * rng.next_normal();
            let tilt = 0.02 * rng.next_normal();
            let rot = Rotation3::from_euler_angles(
                0.1 * rng.next_normal(),
                0.3 * rng.next_normal(),
                0.1 * rng.next_normal(),
            );
            let shift = Vector3::new(
                rng.next_normal(),
                0.1 * rng.next_normal(),
                rng.next_normal(),
            );
            tube()
                .iter()
                .map(|p| {
                    let t = p.y / 1.7;
                    let bump = (-((t - 0.55) / 0.08).powi(2)).exp();
                    let mut q = Point3::new(p.x * wide, p.y * tall, p.z * wide);
                    q.z += belly * bump * (p.z > 0.0) as i32 as f64;
                    q.x += tilt * ramp(t, 0.8, 1.0);
                    rot * q + shift
                })
                .collect()
        })
        .collect()
}

pub fn training_set(n: usize, seed: u64) -> TrainingSet {
    TrainingSet {
        template: template_identity(),
        triangles: triangles(),
        segment_weights: segment_weights(),
        rest_shape: tube(),
        names: (0..n).map(|i| format!("subject{i:03}")).collect(),
        shapes: subjects(n, seed),
    }
}

/// Asserts that the modes of `model` are orthonormal (1e-5).
pub fn check_orthonormal(model: &bodyspace::pca::ShapeModel) {
    for j in 0..model.mode_count() {
        for k in 0..=j {
            let dot: f64 = model
                .mode(j)
                .iter()
                .zip(model.mode(k))
                .map(|(a, b)| *a as f64 * *b as f64)
                .sum();
            let expected = if j == k { 1.0 } else { 0.0 };
            assert!((dot - expected).abs() < 1e-5, "φ{j}·φ{k} = {dot}");
        }
    }
}
