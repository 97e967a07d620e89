//! Input checks of the RBF fit and Procrustes: each failure names the landmarks at fault.

use nalgebra::Point3;

use super::error::{name_list, RbfError};

pub(crate) fn check_len(what: &'static str, expected: usize, got: usize) -> Result<(), RbfError> {
    if expected == got {
        Ok(())
    } else {
        Err(RbfError::LengthMismatch {
            what,
            expected,
            got,
        })
    }
}

pub(crate) fn check_finite(
    names: &[String],
    points: &[Point3<f64>],
    side: &'static str,
) -> Result<(), RbfError> {
    match points.iter().position(|p| !p.iter().all(|v| v.is_finite())) {
        None => Ok(()),
        Some(i) => Err(RbfError::NonFinite {
            name: names.get(i).cloned().unwrap_or_else(|| format!("#{i}")),
            side,
            x: points[i].x,
            y: points[i].y,
            z: points[i].z,
        }),
    }
}

pub(crate) fn check_unique_names(names: &[String], side: &'static str) -> Result<(), RbfError> {
    let mut sorted: Vec<&String> = names.iter().collect();
    sorted.sort();
    match sorted.windows(2).find(|w| w[0] == w[1]) {
        None => Ok(()),
        Some(w) => Err(RbfError::DuplicateName {
            name: w[0].clone(),
            side,
        }),
    }
}

/// Relative tolerance below which two landmarks count as one point: 1e-9 of the set's extent.
const COINCIDENT_RELATIVE: f64 = 1e-9;

pub(crate) fn check_coincident(
    names: &[String],
    points: &[Point3<f64>],
    side: &'static str,
) -> Result<(), RbfError> {
    let tol = COINCIDENT_RELATIVE * extent(points);
    for i in 0..points.len() {
        for j in i + 1..points.len() {
            let distance = (points[i] - points[j]).norm();
            if distance <= tol {
                return Err(RbfError::CoincidentLandmarks {
                    first: names[i].clone(),
                    second: names[j].clone(),
                    distance,
                    side,
                });
            }
        }
    }
    Ok(())
}

/// Bounding-box diagonal of `points` (0 for fewer than two distinct points).
pub(crate) fn extent(points: &[Point3<f64>]) -> f64 {
    let Some(first) = points.first() else {
        return 0.0;
    };
    let (lo, hi) = points
        .iter()
        .fold((*first, *first), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
    (hi - lo).norm()
}

/// Smallest accepted ratio of the least to the largest principal variance of a landmark set
/// before it counts as flat (coplanar) or thin (collinear).
const SPREAD_RELATIVE: f64 = 1e-12;

/// Fails unless `points` span `dims` dimensions (2: not collinear, 3: not coplanar).
pub(crate) fn check_spread(
    names: &[String],
    points: &[Point3<f64>],
    dims: usize,
    side: &'static str,
    purpose: &'static str,
) -> Result<(), RbfError> {
    let n = points.len() as f64;
    let centroid = points
        .iter()
        .fold(nalgebra::Vector3::zeros(), |s, p| s + p.coords)
        / n;
    let cov = points.iter().fold(nalgebra::Matrix3::zeros(), |s, p| {
        let d = p.coords - centroid;
        s + d * d.transpose()
    }) / n;
    let mut ev: Vec<f64> = cov.symmetric_eigenvalues().iter().copied().collect();
    ev.sort_by(|a, b| b.total_cmp(a));
    let largest = ev[0].max(f64::MIN_POSITIVE);
    let (shape, ratio) = if ev[1] / largest < SPREAD_RELATIVE {
        ("collinear or coincident", ev[1] / largest)
    } else if dims == 3 && ev[2] / largest < SPREAD_RELATIVE {
        ("coplanar", ev[2] / largest)
    } else {
        return Ok(());
    };
    Err(RbfError::Degenerate {
        side,
        shape,
        ratio,
        purpose,
        names: name_list(names),
    })
}
