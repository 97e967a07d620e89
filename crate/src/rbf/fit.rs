//! Fitting the RBF network of paper eq. 1–2 ([`RbfNetwork`]) by LU with partial pivoting.
//!
//! One network per coordinate, all three solved at once (three right-hand sides):
//!
//! ```text
//! f(x) = Σ_j w_j Φ(‖x − p_j‖) + a_0 + A·x                (eq. 2, plus the optional affine part)
//!
//! [ K + λI   P ] [ w ]   [ q ]      K_ij = Φ(‖p_i − p_j‖)   n × n
//! [ Pᵀ       0 ] [ a ] = [ 0 ]      P_i  = [1, p_i]          n × 4
//! ```
//!
//! The side conditions Σ w_j = 0, Σ w_j p_j = 0 (the Pᵀ rows) make the affine part carry any
//! affine map exactly; without the affine term the system is just (K + λI) w = q.

use nalgebra::{DMatrix, Point3};

use super::checks::{check_coincident, check_finite, check_len, check_spread, check_unique_names};
use super::error::{name_list, RbfError};
use super::network::{blocks, RbfNetwork};
use super::params::RbfParams;

/// Fits f with f(source_i) = target_i (exactly when λ = 0).
///
/// `names[i]` names pair i in error messages. Shapes: `names`, `source`, `target` all n long.
/// Checks, in order: lengths, parameters, non-finite coordinates, duplicated names, too few
/// pairs, coincident sources (λ = 0), collinear/coplanar sources (affine term), then the
/// reciprocal condition of the LU.
pub fn fit(
    names: &[String],
    source: &[Point3<f64>],
    target: &[Point3<f64>],
    params: &RbfParams,
) -> Result<RbfNetwork, RbfError> {
    let n = source.len();
    check_len("target landmarks", n, target.len())?;
    check_len("landmark names", n, names.len())?;
    params.kernel.validate()?;
    if !(params.lambda.is_finite() && params.lambda >= 0.0) {
        return Err(RbfError::BadParameter {
            name: "lambda",
            value: params.lambda,
            reason: "the smoothing lambda must be finite and >= 0",
        });
    }
    check_finite(names, source, "template")?;
    check_finite(names, target, "scan")?;
    check_unique_names(names, "landmark")?;
    let needed = if params.affine { 4 } else { 1 };
    if n < needed {
        return Err(RbfError::TooFewLandmarks {
            needed,
            got: n,
            purpose: if params.affine {
                "an RBF with affine term"
            } else {
                "an RBF"
            },
            names: name_list(names),
        });
    }
    if params.lambda == 0.0 {
        check_coincident(names, source, "template")?;
    }
    if params.affine {
        check_spread(names, source, 3, "template", "the affine term")?;
    }
    solve(source, target, params).map_err(|e| RbfError::IllConditioned {
        rcond: e.rcond,
        min_rcond: params.min_rcond,
        worst: names
            .get(e.worst_unknown)
            .cloned()
            .unwrap_or_else(|| "the affine term".to_string()),
    })
}

/// Why the system was not solved: its reciprocal condition (0 when the solve itself failed) and
/// the unknown it resolves worst (a landmark index, or ≥ n for the affine term).
struct Unsolvable {
    rcond: f64,
    worst_unknown: usize,
}

/// Builds and solves the system above for checked inputs (`source`, `target` n long).
fn solve(
    source: &[Point3<f64>],
    target: &[Point3<f64>],
    params: &RbfParams,
) -> Result<RbfNetwork, Unsolvable> {
    let n = source.len();
    let m = if params.affine { n + 4 } else { n };
    let mut a = DMatrix::<f64>::zeros(m, m);
    for i in 0..n {
        for j in 0..n {
            a[(i, j)] = params
                .kernel
                .eval_r2((source[i] - source[j]).norm_squared());
        }
        a[(i, i)] += params.lambda;
    }
    if params.affine {
        for (i, p) in source.iter().enumerate() {
            let row = [1.0, p.x, p.y, p.z];
            for (k, v) in row.into_iter().enumerate() {
                a[(i, n + k)] = v;
                a[(n + k, i)] = v;
            }
        }
    }
    let mut b = DMatrix::<f64>::zeros(m, 3);
    for (i, q) in target.iter().enumerate() {
        for k in 0..3 {
            b[(i, k)] = q[k];
        }
    }
    let norm1 = one_norm(&a);
    let lu = a.lu();
    // Partial pivoting permutes rows only, so U's column i still belongs to unknown i: the
    // smallest |U_ii| points at the landmark (or affine term) the system cannot resolve.
    let u = lu.u();
    let worst_unknown = (0..m)
        .min_by(|&i, &j| u[(i, i)].abs().total_cmp(&u[(j, j)].abs()))
        .unwrap_or(0);
    // rcond = 1 / (‖A‖₁ ‖A⁻¹‖₁), exact rather than estimated: A⁻¹ costs (n+4)³ ≈ 10⁶ flops.
    let rcond = match lu.try_inverse() {
        Some(inv) if norm1 > 0.0 => {
            let r = 1.0 / (norm1 * one_norm(&inv));
            if r.is_finite() {
                r
            } else {
                0.0
            }
        }
        _ => 0.0,
    };
    let ill = |rcond| Unsolvable {
        rcond,
        worst_unknown,
    };
    if rcond < params.min_rcond {
        return Err(ill(rcond));
    }
    let x = lu.solve(&b).ok_or_else(|| ill(0.0))?;
    if x.iter().any(|v| !v.is_finite()) {
        return Err(ill(0.0));
    }
    let mut affine = [[0.0; 3]; 4];
    if params.affine {
        for (r, row) in affine.iter_mut().enumerate() {
            for (k, v) in row.iter_mut().enumerate() {
                *v = x[(n + r, k)];
            }
        }
    }
    Ok(RbfNetwork {
        kernel: params.kernel,
        blocks: blocks(source, &x),
        affine,
        rcond,
    })
}

fn one_norm(a: &DMatrix<f64>) -> f64 {
    a.column_iter()
        .map(|c| c.iter().map(|v| v.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}
