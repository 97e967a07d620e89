//! A procedural body-like test subject for the RBF tests, the sweep and the benchmark: tubes and
//! ellipsoids in metres (y up, facing +z, subject's left at +x, feet on y = 0) carrying the 73
//! CAESAR landmark names at plausible places, and a known smooth non-linear "subject"
//! deformation (taller, arms raised, belly, then millimetres and z-up as CAESAR scans are).
//! It stands in for the real template/synthetic population until those land; see docs/rbf.md.

#![allow(dead_code)]

use bodyspace::landmarks::{Landmark, LandmarkSet, CAESAR_LANDMARKS};
use bodyspace::mesh::Mesh;
use nalgebra::{Point3, Rotation3, Vector3};

/// A tube from `a` to `b`, radii (across x, across z) linearly from `ra` to `rb`.
fn tube(
    mesh: &mut Mesh,
    a: [f64; 3],
    b: [f64; 3],
    ra: (f64, f64),
    rb: (f64, f64),
    rings: usize,
    around: usize,
) {
    let a = Vector3::from(a);
    let b = Vector3::from(b);
    let axis = (b - a).normalize();
    // A stable pair of directions across the axis, the first as close to x as possible.
    let ex = (Vector3::x() - axis * axis.x)
        .try_normalize(1e-9)
        .unwrap_or(Vector3::z());
    let ez = axis.cross(&ex);
    let base = mesh.positions.len() as u32;
    for i in 0..rings {
        let t = i as f64 / (rings - 1) as f64;
        let c = a + (b - a) * t;
        let (rx, rz) = (ra.0 + (rb.0 - ra.0) * t, ra.1 + (rb.1 - ra.1) * t);
        for j in 0..around {
            let th = std::f64::consts::TAU * j as f64 / around as f64;
            mesh.positions
                .push(Point3::from(c + ex * rx * th.cos() + ez * rz * th.sin()));
        }
    }
    for i in 0..rings as u32 - 1 {
        for j in 0..around as u32 {
            let k = (j + 1) % around as u32;
            let (p, q) = (base + i * around as u32, base + (i + 1) * around as u32);
            mesh.triangles.push([p + j, p + k, q + j]);
            mesh.triangles.push([p + k, q + k, q + j]);
        }
    }
}

/// An ellipsoid centred at `c` with radii `r`.
fn ellipsoid(mesh: &mut Mesh, c: [f64; 3], r: [f64; 3], rings: usize, around: usize) {
    let base = mesh.positions.len() as u32;
    for i in 0..rings {
        let phi = std::f64::consts::PI * (i as f64 + 0.5) / rings as f64;
        for j in 0..around {
            let th = std::f64::consts::TAU * j as f64 / around as f64;
            mesh.positions.push(Point3::new(
                c[0] + r[0] * phi.sin() * th.cos(),
                c[1] + r[1] * phi.cos(),
                c[2] + r[2] * phi.sin() * th.sin(),
            ));
        }
    }
    for i in 0..rings as u32 - 1 {
        for j in 0..around as u32 {
            let k = (j + 1) % around as u32;
            let (p, q) = (base + i * around as u32, base + (i + 1) * around as u32);
            mesh.triangles.push([p + j, q + j, p + k]);
            mesh.triangles.push([p + k, q + j, q + k]);
        }
    }
}

/// The body surface with about `density`² × 40 vertices (density 10 → ~4K, 40 → ~65K).
pub fn body(density: usize) -> Mesh {
    let d = density.max(3);
    let mut m = Mesh::default();
    tube(
        &mut m,
        [0.0, 0.85, 0.0],
        [0.0, 1.45, 0.0],
        (0.17, 0.11),
        (0.19, 0.11),
        4 * d,
        4 * d,
    );
    tube(
        &mut m,
        [0.0, 1.45, 0.0],
        [0.0, 1.56, 0.0],
        (0.06, 0.06),
        (0.055, 0.055),
        d,
        2 * d,
    );
    ellipsoid(&mut m, [0.0, 1.65, 0.0], [0.08, 0.11, 0.10], 2 * d, 2 * d);
    for s in [-1.0, 1.0] {
        let x = |v: f64| s * v;
        tube(
            &mut m,
            [x(0.19), 1.42, 0.0],
            [x(0.30), 1.15, 0.0],
            (0.045, 0.045),
            (0.04, 0.04),
            2 * d,
            d,
        );
        tube(
            &mut m,
            [x(0.30), 1.15, 0.0],
            [x(0.38), 0.88, 0.02],
            (0.038, 0.038),
            (0.03, 0.025),
            2 * d,
            d,
        );
        tube(
            &mut m,
            [x(0.38), 0.88, 0.02],
            [x(0.42), 0.70, 0.03],
            (0.03, 0.015),
            (0.02, 0.01),
            d,
            d,
        );
        tube(
            &mut m,
            [x(0.09), 0.88, 0.0],
            [x(0.10), 0.48, 0.0],
            (0.08, 0.08),
            (0.055, 0.055),
            3 * d,
            2 * d,
        );
        tube(
            &mut m,
            [x(0.10), 0.48, 0.0],
            [x(0.10), 0.08, 0.0],
            (0.05, 0.05),
            (0.035, 0.035),
            3 * d,
            2 * d,
        );
        tube(
            &mut m,
            [x(0.10), 0.035, -0.05],
            [x(0.11), 0.035, 0.20],
            (0.04, 0.035),
            (0.04, 0.02),
            2 * d,
            d,
        );
    }
    m
}

/// Approximate landmark places: (canonical name without side, right-side point; x < 0).
/// Midline names have x = 0; every other one is mirrored for the left side.
const PLACES: [(&str, [f64; 3]); 41] = [
    ("Sellion", [0.0, 1.68, 0.10]),
    ("Supramenton", [0.0, 1.56, 0.08]),
    ("Nuchale", [0.0, 1.60, -0.09]),
    ("Suprasternale", [0.0, 1.44, 0.08]),
    ("Substernale", [0.0, 1.25, 0.11]),
    ("Cervicale", [0.0, 1.48, -0.07]),
    ("10th Rib Midspine", [0.0, 1.20, -0.11]),
    ("Waist, Preferred, Post.", [0.0, 1.05, -0.11]),
    ("Crotch", [0.0, 0.84, 0.0]),
    ("Infraorbitale", [-0.03, 1.66, 0.09]),
    ("Tragion", [-0.08, 1.65, 0.0]),
    ("Gonion", [-0.06, 1.58, 0.03]),
    ("Clavicale", [-0.05, 1.45, 0.07]),
    ("Thelion/Bustpoint", [-0.09, 1.30, 0.12]),
    ("10th Rib", [-0.15, 1.18, 0.05]),
    ("ASIS", [-0.11, 0.98, 0.09]),
    ("Iliocristale", [-0.16, 1.02, 0.0]),
    ("Trochanterion", [-0.17, 0.88, 0.0]),
    ("PSIS", [-0.05, 1.00, -0.10]),
    ("Acromion", [-0.20, 1.46, 0.0]),
    ("Axilla, Ant.", [-0.16, 1.35, 0.07]),
    ("Axilla, Post.", [-0.16, 1.35, -0.07]),
    ("Radial Styloid", [-0.39, 0.89, 0.05]),
    ("Olecranon", [-0.30, 1.15, -0.04]),
    ("Humeral Lateral Epicn", [-0.34, 1.15, 0.0]),
    ("Humeral Medial Epicn", [-0.26, 1.15, 0.0]),
    ("Radiale", [-0.33, 1.13, 0.02]),
    ("Metacarpal Phal. II", [-0.40, 0.79, 0.05]),
    ("Dactylion", [-0.42, 0.69, 0.03]),
    ("Ulnar Styloid", [-0.37, 0.88, -0.02]),
    ("Metacarpal Phal. V", [-0.43, 0.80, 0.0]),
    ("Knee Crease", [-0.10, 0.48, -0.06]),
    ("Femoral Lateral Epicn", [-0.155, 0.49, 0.0]),
    ("Femoral Medial Epicn", [-0.045, 0.49, 0.0]),
    ("Metatarsal Phal. V", [-0.145, 0.03, 0.12]),
    ("Lateral Malleolus", [-0.135, 0.08, 0.0]),
    ("Medial Malleolus", [-0.065, 0.09, 0.0]),
    ("Sphyrion", [-0.07, 0.06, 0.01]),
    ("Metatarsal Phal. I", [-0.075, 0.03, 0.13]),
    ("Calcaneous, Post.", [-0.10, 0.04, -0.09]),
    ("Digit II", [-0.10, 0.03, 0.21]),
];

/// The 73 CAESAR landmarks on `mesh` (each snapped to its nearest vertex), CAESAR order.
pub fn landmarks(mesh: &Mesh) -> LandmarkSet {
    let place = |name: &str| -> [f64; 3] {
        let (bare, sign) = if let Some(n) = name.strip_prefix("Rt. ") {
            (n, 1.0)
        } else if let Some(n) = name.strip_prefix("Lt. ") {
            (n, -1.0)
        } else {
            (name, 1.0)
        };
        let p = PLACES
            .iter()
            .find(|(n, _)| *n == bare)
            .map(|(_, p)| *p)
            .unwrap_or_else(|| panic!("no place for {name}"));
        [p[0] * sign, p[1], p[2]]
    };
    let landmarks = CAESAR_LANDMARKS
        .iter()
        .map(|c| {
            let target = Point3::from(place(c.name));
            let position = *mesh
                .positions
                .iter()
                .min_by(|a, b| (*a - target).norm().total_cmp(&(*b - target).norm()))
                .unwrap();
            Landmark {
                name: c.name.to_string(),
                position,
            }
        })
        .collect();
    LandmarkSet {
        landmarks,
        ..LandmarkSet::default()
    }
}

fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The subject's shape in the template frame (metres): 6 % taller, belly and hips 15 % wider,
/// arms raised by up to 12° about the shoulders, blended smoothly across the armpit.
pub fn subject_shape(p: &Point3<f64>) -> Point3<f64> {
    let mut v = p.coords;
    let belly = 1.0 + 0.15 * (-((p.y - 1.0) / 0.15).powi(2)).exp();
    v.x *= belly;
    v.z *= belly;
    for s in [-1.0_f64, 1.0] {
        let w = smoothstep(0.16, 0.24, s * p.x) * smoothstep(0.75, 1.0, p.y);
        if w > 0.0 {
            let shoulder = Vector3::new(s * 0.19, 1.42, 0.0);
            let r = Rotation3::from_axis_angle(&Vector3::z_axis(), s * 12f64.to_radians() * w);
            v = shoulder + r * (v - shoulder);
        }
    }
    v.y *= 1.06;
    Point3::from(v)
}

/// Template metres, y-up → scan millimetres, z-up (x stays, y → z, z → −y), shifted.
pub fn to_scan_frame(p: &Point3<f64>) -> Point3<f64> {
    Point3::new(
        1000.0 * p.x + 120.0,
        -1000.0 * p.z - 40.0,
        1000.0 * p.y + 5.0,
    )
}

/// The full ground-truth map template → scan.
pub fn subject(p: &Point3<f64>) -> Point3<f64> {
    to_scan_frame(&subject_shape(p))
}

/// Deterministic pseudo-random offsets in [−a, a]³ (a 64-bit LCG; no crate needed for a test).
pub fn jitter(points: &mut [Landmark], amplitude: f64, seed: u64) {
    let mut state = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    for l in points {
        l.position += Vector3::new(next(), next(), next()) * amplitude;
    }
}
