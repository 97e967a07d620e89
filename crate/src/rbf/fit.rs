//! The RBF network of paper eq. 1–2, fitted by LU with partial pivoting, and its evaluation.
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

use super::error::{name_list, RbfError};
use super::fast_math;
use super::kernel::Kernel;
use super::params::RbfParams;

/// A fitted RBF network mapping R³ → R³.
#[derive(Debug, Clone, PartialEq)]
pub struct RbfNetwork {
    kernel: Kernel,
    /// Centres p_j and weights w_j per coordinate, in vectorisable blocks.
    blocks: Vec<Block>,
    /// Affine part: row 0 the constant a_0, rows 1..4 the linear map (x, y, z → output).
    /// All zero when the fit had no affine term.
    affine: [[f64; 3]; 4],
    rcond: f64,
    /// n, the number of real (unpadded) centres.
    centres: usize,
}

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
    solve(names, source, target, params)
}

fn solve(
    names: &[String],
    source: &[Point3<f64>],
    target: &[Point3<f64>],
    params: &RbfParams,
) -> Result<RbfNetwork, RbfError> {
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
    let worst_col = (0..m)
        .min_by(|&i, &j| u[(i, i)].abs().total_cmp(&u[(j, j)].abs()))
        .unwrap_or(0);
    let worst = if worst_col < n {
        names[worst_col].clone()
    } else {
        "the affine term".to_string()
    };
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
    let ill = |rcond| RbfError::IllConditioned {
        rcond,
        min_rcond: params.min_rcond,
        worst: worst.clone(),
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
        centres: n,
        affine,
        rcond,
    })
}

impl RbfNetwork {
    /// The kernel the network was fitted with.
    pub fn kernel(&self) -> Kernel {
        self.kernel
    }

    /// Reciprocal 1-norm condition number of the fitted system (1 = perfect, ~1e-16 = singular).
    pub fn rcond(&self) -> f64 {
        self.rcond
    }

    /// Number of centres n.
    pub fn centre_count(&self) -> usize {
        self.centres
    }

    /// f(x) for one point.
    pub fn evaluate(&self, x: &Point3<f64>) -> Point3<f64> {
        let mut out = [Point3::origin()];
        self.warp_into(std::slice::from_ref(x), &mut out);
        out[0]
    }

    /// f applied to every point: `#V` points in, `#V` points out.
    pub fn warp(&self, points: &[Point3<f64>]) -> Vec<Point3<f64>> {
        let mut out = vec![Point3::origin(); points.len()];
        self.warp_into(points, &mut out);
        out
    }

    /// f applied to every point of `points`, written to `out` (same length; extra entries of
    /// either are ignored). No allocation per vertex; the kernel is matched once, outside the
    /// loop. Natively the points are split over the available cores (scoped std threads).
    pub fn warp_into(&self, points: &[Point3<f64>], out: &mut [Point3<f64>]) {
        let len = points.len().min(out.len());
        let (points, out) = (&points[..len], &mut out[..len]);
        #[cfg(not(target_arch = "wasm32"))]
        {
            // Below ~20K points a thread costs more than it saves.
            let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
            if threads > 1 && len >= 20_000 {
                let chunk = len.div_ceil(threads);
                std::thread::scope(|scope| {
                    for (p, o) in points.chunks(chunk).zip(out.chunks_mut(chunk)) {
                        scope.spawn(move || self.warp_serial(p, o));
                    }
                });
                return;
            }
        }
        self.warp_serial(points, out);
    }

    /// [`Self::warp_into`] on the calling thread only (for benchmarks and single-threaded hosts).
    pub fn warp_serial(&self, points: &[Point3<f64>], out: &mut [Point3<f64>]) {
        match self.kernel {
            Kernel::ThinPlate => self.warp_with(points, out, |r2| {
                // r2 = 0 would give 0·(−∞); max() keeps the log finite and the product 0.
                0.5 * r2 * fast_math::ln_positive(r2.max(f64::MIN_POSITIVE))
            }),
            Kernel::Multiquadric { s } => {
                let s2 = s * s;
                self.warp_with(points, out, |r2| (r2 + s2).sqrt())
            }
            Kernel::Gaussian { c } => {
                let inv_c2 = 1.0 / (c * c);
                self.warp_with(points, out, |r2| fast_math::exp_nonpositive(-r2 * inv_c2))
            }
        }
    }

    /// The warp loop: LANES independent accumulators per coordinate so the compiler can
    /// vectorise across centres (a single running sum would force sequential order).
    #[inline(always)]
    fn warp_with(&self, points: &[Point3<f64>], out: &mut [Point3<f64>], phi: impl Fn(f64) -> f64) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma")
            {
                // SAFETY: the CPU was just checked for the features the function is built with.
                unsafe { warp_blocks_avx2(&self.blocks, &self.affine, points, out, phi) };
                return;
            }
        }
        warp_blocks(&self.blocks, &self.affine, points, out, phi);
    }
}

/// [`warp_blocks`] compiled for AVX2 + FMA: 4 lanes per instruction instead of SSE2's 2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn warp_blocks_avx2(
    blocks: &[Block],
    affine: &[[f64; 3]; 4],
    points: &[Point3<f64>],
    out: &mut [Point3<f64>],
    phi: impl Fn(f64) -> f64,
) {
    warp_blocks(blocks, affine, points, out, phi)
}

#[inline(always)]
fn warp_blocks(
    blocks: &[Block],
    a: &[[f64; 3]; 4],
    points: &[Point3<f64>],
    out: &mut [Point3<f64>],
    phi: impl Fn(f64) -> f64,
) {
    for (p, o) in points.iter().zip(out.iter_mut()) {
        let mut ax = [0.0; LANES];
        let mut ay = [0.0; LANES];
        let mut az = [0.0; LANES];
        for b in blocks {
            for l in 0..LANES {
                let (dx, dy, dz) = (p.x - b.cx[l], p.y - b.cy[l], p.z - b.cz[l]);
                let k = phi(dx * dx + dy * dy + dz * dz);
                ax[l] += b.wx[l] * k;
                ay[l] += b.wy[l] * k;
                az[l] += b.wz[l] * k;
            }
        }
        let (fx, fy, fz) = (
            ax.iter().sum::<f64>(),
            ay.iter().sum::<f64>(),
            az.iter().sum::<f64>(),
        );
        *o = Point3::new(
            fx + a[0][0] + a[1][0] * p.x + a[2][0] * p.y + a[3][0] * p.z,
            fy + a[0][1] + a[1][1] * p.x + a[2][1] * p.y + a[3][1] * p.z,
            fz + a[0][2] + a[1][2] * p.x + a[2][2] * p.y + a[3][2] * p.z,
        );
    }
}

/// LANES centres and their weights, side by side so the warp loop vectorises.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Block {
    cx: [f64; LANES],
    cy: [f64; LANES],
    cz: [f64; LANES],
    wx: [f64; LANES],
    wy: [f64; LANES],
    wz: [f64; LANES],
}

/// Centres in blocks of LANES; the last block is padded with zero-weight copies of centre 0.
fn blocks(source: &[Point3<f64>], weights: &DMatrix<f64>) -> Vec<Block> {
    let n = source.len();
    (0..n.div_ceil(LANES))
        .map(|b| {
            let mut block = Block {
                cx: [source[0].x; LANES],
                cy: [source[0].y; LANES],
                cz: [source[0].z; LANES],
                wx: [0.0; LANES],
                wy: [0.0; LANES],
                wz: [0.0; LANES],
            };
            for l in 0..LANES {
                let j = b * LANES + l;
                if j < n {
                    block.cx[l] = source[j].x;
                    block.cy[l] = source[j].y;
                    block.cz[l] = source[j].z;
                    block.wx[l] = weights[(j, 0)];
                    block.wy[l] = weights[(j, 1)];
                    block.wz[l] = weights[(j, 2)];
                }
            }
            block
        })
        .collect()
}

/// Centres per block of the warp loop (4 f64 = one AVX2 register).
const LANES: usize = 4;

fn one_norm(a: &DMatrix<f64>) -> f64 {
    a.column_iter()
        .map(|c| c.iter().map(|v| v.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

fn check_len(what: &'static str, expected: usize, got: usize) -> Result<(), RbfError> {
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

fn check_coincident(
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
