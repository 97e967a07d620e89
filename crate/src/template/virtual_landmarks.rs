//! The 12 virtual landmarks (paper §3.1: 73 + 12 = 85 landmark pairs steer the RBF warp where
//! anatomy gives no landmark: top of the head, soles, the middle of the long bones, the belly).
//!
//! Each is made from the 73 CAESAR landmarks and the surface alone, so the same rule runs on the
//! template and on any scan that has the 73:
//!
//! | name | rule |
//! |---|---|
//! | `Virtual Head Top` | highest surface point within 8 cm (horizontally) of the mid-tragion point |
//! | `Lt./Rt. Virtual Sole` | x, z = mean of Calcaneous Post., Metatarsal Phal. I and V; the lowest surface point within 3 cm horizontally |
//! | `Lt./Rt. Virtual Upper Arm` | surface point nearest to the midpoint of Acromion and Olecranon |
//! | `Lt./Rt. Virtual Forearm` | surface point nearest to the midpoint of Radiale and Ulnar Styloid |
//! | `Lt./Rt. Virtual Thigh` | surface point nearest to the midpoint of Trochanterion and Femoral Lateral Epicn |
//! | `Lt./Rt. Virtual Shank` | surface point nearest to the midpoint of Femoral Lateral Epicn and Lateral Malleolus |
//! | `Virtual Belly` | front-most surface point (max z) within 3 cm in x and y of the midpoint of Substernale and the mean of the two ASIS |
//!
//! "Surface point" is a mesh vertex; on the template it is a template vertex, on a scan a scan
//! vertex.

use nalgebra::Point3;

use super::error::TemplateError;
use crate::landmarks::{Landmark, LandmarkSet};
use crate::mesh::Mesh;

/// Names of the virtual landmarks, in the order [`virtual_landmarks`] returns them.
pub const VIRTUAL_LANDMARKS: [&str; 12] = [
    "Virtual Head Top",
    "Lt. Virtual Sole",
    "Rt. Virtual Sole",
    "Lt. Virtual Upper Arm",
    "Rt. Virtual Upper Arm",
    "Lt. Virtual Forearm",
    "Rt. Virtual Forearm",
    "Lt. Virtual Thigh",
    "Rt. Virtual Thigh",
    "Lt. Virtual Shank",
    "Rt. Virtual Shank",
    "Virtual Belly",
];

/// The 12 virtual landmarks as (name, mesh vertex) from the 73 landmarks and the surface.
pub fn virtual_landmark_vertices(
    landmarks: &LandmarkSet,
    mesh: &Mesh,
) -> Result<Vec<(String, u32)>, TemplateError> {
    if mesh.positions.is_empty() {
        return Err(TemplateError::Format(
            "virtual landmarks need a non-empty surface".into(),
        ));
    }
    let get = |name: &str| {
        landmarks.get(name).ok_or_else(|| {
            TemplateError::Landmark(name.into(), "needed for the virtual landmarks".into())
        })
    };
    let mid = |a: Point3<f64>, b: Point3<f64>| Point3::from((a.coords + b.coords) / 2.0);
    let nearest = |q: Point3<f64>| nearest_vertex(mesh, &q);
    let horizontal =
        |p: &Point3<f64>, q: &Point3<f64>| ((p.x - q.x).powi(2) + (p.z - q.z).powi(2)).sqrt();
    let extreme_y = |centre: Point3<f64>, radius: f64, up: bool| -> u32 {
        let pick = (0..mesh.positions.len() as u32)
            .filter(|&v| horizontal(&mesh.positions[v as usize], &centre) < radius)
            .max_by(|&a, &b| {
                let (ya, yb) = (mesh.positions[a as usize].y, mesh.positions[b as usize].y);
                if up {
                    ya.total_cmp(&yb)
                } else {
                    yb.total_cmp(&ya)
                }
            });
        pick.unwrap_or_else(|| nearest(centre))
    };
    let mut out = Vec::with_capacity(12);
    let ear = mid(get("Rt. Tragion")?, get("Lt. Tragion")?);
    out.push(("Virtual Head Top".to_string(), extreme_y(ear, 0.08, true)));
    for side in ["Lt.", "Rt."] {
        let l = |n: &str| get(&format!("{side} {n}"));
        let foot = Point3::from(
            (l("Calcaneous, Post.")?.coords
                + l("Metatarsal Phal. I")?.coords
                + l("Metatarsal Phal. V")?.coords)
                / 3.0,
        );
        out.push((format!("{side} Virtual Sole"), extreme_y(foot, 0.03, false)));
    }
    let pairs = [
        ("Upper Arm", "Acromion", "Olecranon"),
        ("Forearm", "Radiale", "Ulnar Styloid"),
        ("Thigh", "Trochanterion", "Femoral Lateral Epicn"),
        ("Shank", "Femoral Lateral Epicn", "Lateral Malleolus"),
    ];
    for (name, a, b) in pairs {
        for side in ["Lt.", "Rt."] {
            let m = mid(get(&format!("{side} {a}"))?, get(&format!("{side} {b}"))?);
            out.push((format!("{side} Virtual {name}"), nearest(m)));
        }
    }
    let asis = mid(get("Rt. ASIS")?, get("Lt. ASIS")?);
    let belly = mid(get("Substernale")?, asis);
    let front = (0..mesh.positions.len() as u32)
        .filter(|&v| {
            let p = mesh.positions[v as usize];
            (p.x - belly.x).abs() < 0.03 && (p.y - belly.y).abs() < 0.03
        })
        .max_by(|&a, &b| {
            mesh.positions[a as usize]
                .z
                .total_cmp(&mesh.positions[b as usize].z)
        })
        .unwrap_or_else(|| nearest(belly));
    out.push(("Virtual Belly".to_string(), front));
    Ok(out)
}

/// The 12 virtual landmarks as positions (see [`virtual_landmark_vertices`]).
pub fn virtual_landmarks(
    landmarks: &LandmarkSet,
    mesh: &Mesh,
) -> Result<Vec<Landmark>, TemplateError> {
    Ok(virtual_landmark_vertices(landmarks, mesh)?
        .into_iter()
        .map(|(name, v)| Landmark {
            name,
            position: mesh.positions[v as usize],
        })
        .collect())
}

fn nearest_vertex(mesh: &Mesh, q: &Point3<f64>) -> u32 {
    (0..mesh.positions.len() as u32)
        .min_by(|&a, &b| {
            (mesh.positions[a as usize] - q)
                .norm_squared()
                .total_cmp(&(mesh.positions[b as usize] - q).norm_squared())
        })
        .unwrap_or(0)
}
