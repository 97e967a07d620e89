//! Synthetic surfaces for the fine-alignment tests (built in the tests, no files read).
#![allow(dead_code)]

use bodyspace::mesh::Mesh;
use nalgebra::{Point3, Vector3};

/// Tiny deterministic generator (SplitMix64) so tests need no random-number crate.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [-1, 1).
    pub fn symmetric(&mut self) -> f64 {
        2.0 * self.next_f64() - 1.0
    }
}

/// A UV sphere of unit radius: `rings` latitude bands, `segments` longitudes, triangles CCW
/// seen from outside.
pub fn uv_sphere(rings: usize, segments: usize) -> Mesh {
    let mut positions = vec![Point3::new(0.0, 0.0, 1.0)];
    for r in 1..rings {
        let theta = std::f64::consts::PI * r as f64 / rings as f64;
        for s in 0..segments {
            let phi = 2.0 * std::f64::consts::PI * s as f64 / segments as f64;
            positions.push(Point3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    positions.push(Point3::new(0.0, 0.0, -1.0));
    let south = (positions.len() - 1) as u32;
    let ring = |r: usize, s: usize| (1 + (r - 1) * segments + s % segments) as u32;
    let mut triangles = Vec::new();
    for s in 0..segments {
        triangles.push([0, ring(1, s), ring(1, s + 1)]);
        triangles.push([south, ring(rings - 1, s + 1), ring(rings - 1, s)]);
    }
    for r in 1..rings - 1 {
        for s in 0..segments {
            let (a, b, c, d) = (
                ring(r, s),
                ring(r, s + 1),
                ring(r + 1, s),
                ring(r + 1, s + 1),
            );
            triangles.push([a, c, d]);
            triangles.push([a, d, b]);
        }
    }
    Mesh::new(positions, triangles)
}

/// An open tube of radius `radius` around the vertical axis through (`cx`, `cy`), from z0 to z1,
/// triangles CCW seen from outside.
pub fn tube(
    cx: f64,
    cy: f64,
    radius: f64,
    z0: f64,
    z1: f64,
    rings: usize,
    segments: usize,
) -> Mesh {
    let mut positions = Vec::new();
    for r in 0..=rings {
        let z = z0 + (z1 - z0) * r as f64 / rings as f64;
        for s in 0..segments {
            let phi = 2.0 * std::f64::consts::PI * s as f64 / segments as f64;
            positions.push(Point3::new(
                cx + radius * phi.cos(),
                cy + radius * phi.sin(),
                z,
            ));
        }
    }
    let at = |r: usize, s: usize| (r * segments + s % segments) as u32;
    let mut triangles = Vec::new();
    for r in 0..rings {
        for s in 0..segments {
            triangles.push([at(r, s), at(r, s + 1), at(r + 1, s + 1)]);
            triangles.push([at(r, s), at(r + 1, s + 1), at(r + 1, s)]);
        }
    }
    Mesh::new(positions, triangles)
}

/// Concatenates meshes (indices shifted).
pub fn merge(parts: &[Mesh]) -> Mesh {
    let mut out = Mesh::default();
    for m in parts {
        let base = out.positions.len() as u32;
        out.positions.extend_from_slice(&m.positions);
        out.triangles
            .extend(m.triangles.iter().map(|t| t.map(|i| i + base)));
    }
    out
}

/// Maps every vertex through `f`.
pub fn map(mesh: &Mesh, f: impl Fn(&Point3<f64>) -> Point3<f64>) -> Mesh {
    Mesh::new(
        mesh.positions.iter().map(f).collect(),
        mesh.triangles.clone(),
    )
}

/// The "subject": an ellipsoid with semi-axes (a, b, c) and a smooth bump, centred at `centre`.
pub fn ellipsoid_point(p: &Point3<f64>, axes: Vector3<f64>, centre: Vector3<f64>) -> Point3<f64> {
    let bump = 1.0 + 0.08 * (3.0 * p.x).sin() * (2.0 * p.z).cos();
    Point3::from(p.coords.component_mul(&axes) * bump + centre)
}

/// Radius (m) and centre of the exact sphere of [`agreement_case`].
pub const AGREEMENT_RADIUS: f64 = 0.2;
pub const AGREEMENT_CENTRE: Vector3<f64> = Vector3::new(0.03, -0.02, 0.9);

/// The native-vs-WASM agreement case: a noise-free sphere scan (radius 0.2 m, ≈ 3.2K vertices)
/// and a coarse template sphere 5 % too large and 6 mm off centre. Known answer: the fitted
/// template lies on the sphere (up to the scan's chord sag, 0.15 mm) around its centre.
pub fn agreement_case() -> (Mesh, Mesh) {
    let scan = map(&uv_sphere(40, 80), |p| {
        Point3::from(p.coords * AGREEMENT_RADIUS + AGREEMENT_CENTRE)
    });
    let template = map(&uv_sphere(24, 48), |p| {
        Point3::from(
            p.coords * (AGREEMENT_RADIUS * 1.05)
                + AGREEMENT_CENTRE
                + Vector3::new(0.004, -0.003, 0.003),
        )
    });
    (scan, template)
}

/// The tolerance band both builds are held to (metres): every fitted vertex within 1 mm of the
/// sphere, mean radial error under 0.3 mm, scan→template RMS under 1 mm. (Not the vertex
/// centroid: on a sphere vertices may slide tangentially, which the energy barely penalises.)
pub fn check_agreement(positions: &[Point3<f64>], scan_to_template_rms: f64) {
    let radial: Vec<f64> = positions
        .iter()
        .map(|p| ((p.coords - AGREEMENT_CENTRE).norm() - AGREEMENT_RADIUS).abs())
        .collect();
    let worst = radial.iter().cloned().fold(0.0, f64::max);
    let mean = radial.iter().sum::<f64>() / radial.len() as f64;
    assert!(worst < 1e-3, "worst radial error {worst} m");
    assert!(mean < 3e-4, "mean radial error {mean} m");
    assert!(
        scan_to_template_rms < 1e-3,
        "scan→template RMS {scan_to_template_rms} m"
    );
}
