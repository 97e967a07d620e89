//! Region flags: hands, ears, soles and surface no scanner can see.
//!
//! * HAND: MakeHuman skin weight on finger + metacarpal bones ≥ ½.
//! * EAR: head vertices within [`RegionParams::ear_radius`] of the ear centre (the lateral-most
//!   head vertex behind the eye, between 5 cm below and 1 cm above it) that stand out laterally
//!   from the skull (|x| ≥ ear centre |x| − [`RegionParams::ear_depth`]).
//! * SOLE: leg vertices below 1.5 cm whose normal points down (n_y < −½).
//! * UNSEEN: head vertices near the mouth, nose and eyes from which every ray of a small cone
//!   around the outward normal hits the skin again within 8 cm (the inner mouth cavity and the
//!   nostrils: a scanner's light cannot reach them).

use nalgebra::{Point3, Vector3};

use super::super::flags::RegionFlags;
use super::super::segment::Segment;
use super::context::BuildContext;
use crate::mesh::ray::ray_triangle;
use crate::template::TemplateError;

/// Parameters of the region flags.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionParams {
    /// Radius around the ear centre, metres (default 0.032).
    pub ear_radius: f64,
    /// How far medial of the ear centre the ear reaches, metres (default 0.012).
    pub ear_depth: f64,
    /// Ray length of the visibility test, metres (default 0.08).
    pub ray_length: f64,
}

impl Default for RegionParams {
    fn default() -> Self {
        Self {
            ear_radius: 0.032,
            ear_depth: 0.012,
            ray_length: 0.08,
        }
    }
}

/// The ear centre on the side `sign` (+1 left, −1 right).
pub fn ear_centre(ctx: &BuildContext, hard: &[Segment], sign: f64) -> Result<u32, TemplateError> {
    let eye = ctx.joint("eye.L____head")?;
    (0..ctx.vertex_count() as u32)
        .filter(|&v| {
            let p = ctx.p(v);
            hard[v as usize] == Segment::Head
                && p.x * sign > 0.0
                && p.y > eye.y - 0.05
                && p.y < eye.y + 0.01
                && p.z < eye.z - 0.06
                && p.z > eye.z - 0.16
        })
        .max_by(|&a, &b| (ctx.p(a).x * sign).total_cmp(&(ctx.p(b).x * sign)))
        .ok_or_else(|| {
            TemplateError::Landmark("ear centre".into(), "no head vertex behind the eye".into())
        })
}

/// Flags per vertex.
pub fn region_flags(
    ctx: &BuildContext,
    hard: &[Segment],
    params: &RegionParams,
) -> Result<Vec<u8>, TemplateError> {
    let n = ctx.vertex_count();
    let mut flags = vec![0u8; n];
    for v in 0..n as u32 {
        let hand = ctx.bone_weight(v, |b| {
            b.starts_with("finger") || b.starts_with("metacarpal")
        });
        if hand >= 0.5 {
            flags[v as usize] |= RegionFlags::HAND;
        }
        let p = ctx.p(v);
        let leg = matches!(hard[v as usize], Segment::LeftLeg | Segment::RightLeg);
        if leg && p.y < 0.015 && ctx.normals[v as usize].y < -0.5 {
            flags[v as usize] |= RegionFlags::SOLE;
        }
    }
    for sign in [1.0, -1.0] {
        let c = ctx.p(ear_centre(ctx, hard, sign)?);
        for v in 0..n as u32 {
            let p = ctx.p(v);
            if hard[v as usize] == Segment::Head
                && (p - c).norm() < params.ear_radius
                && p.x * sign >= c.x * sign - params.ear_depth
            {
                flags[v as usize] |= RegionFlags::EAR;
            }
        }
    }
    for v in unseen_vertices(ctx, hard, params)? {
        flags[v as usize] |= RegionFlags::UNSEEN;
    }
    Ok(flags)
}

fn unseen_vertices(
    ctx: &BuildContext,
    hard: &[Segment],
    params: &RegionParams,
) -> Result<Vec<u32>, TemplateError> {
    let centres = [
        ctx.joint("tongue01____head")?,
        ctx.joint("eye.L____head")?,
        ctx.joint("eye.R____head")?,
    ];
    let near = |p: &Point3<f64>, r: f64| centres.iter().any(|c| (p - c).norm() < r);
    let candidates: Vec<u32> = (0..ctx.vertex_count() as u32)
        .filter(|&v| hard[v as usize] == Segment::Head && near(&ctx.p(v), 0.07))
        .collect();
    let tris: Vec<[Point3<f64>; 3]> = ctx
        .mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| ctx.p(i)))
        .filter(|t| t.iter().any(|p| near(p, 0.07 + params.ray_length)))
        .collect();
    let mut out = Vec::new();
    for v in candidates {
        let p = ctx.p(v);
        let n = ctx.normals[v as usize];
        let (u, w) = orthonormal(&n);
        let tilt = 0.6f64; // ≈ 35°
        let dirs = [
            n,
            (n + u * tilt).normalize(),
            (n - u * tilt).normalize(),
            (n + w * tilt).normalize(),
            (n - w * tilt).normalize(),
        ];
        let origin = p + n * 1e-5;
        if dirs.iter().all(|d| {
            tris.iter()
                .any(|t| ray_hits(&origin, d, t, params.ray_length))
        }) {
            out.push(v);
        }
    }
    Ok(out)
}

fn orthonormal(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let a = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let u = n.cross(&a).normalize();
    (u, n.cross(&u))
}

/// Whether the ray `o + t d`, `1e-6 < t < max`, crosses the triangle.
fn ray_hits(o: &Point3<f64>, d: &Vector3<f64>, t: &[Point3<f64>; 3], max: f64) -> bool {
    ray_triangle(o, d, [&t[0], &t[1], &t[2]], 1e-14)
        .is_some_and(|(dist, ..)| dist > 1e-6 && dist < max)
}
