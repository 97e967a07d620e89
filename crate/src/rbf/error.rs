//! Errors of the RBF rough deformation: every message names the landmarks at fault.

use thiserror::Error;

/// Why a landmark set cannot be fitted or warped. No variant is ever replaced by NaN output:
/// every fit either returns finite weights or one of these.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RbfError {
    /// Parallel slices (names, source, target) disagree in length.
    #[error("{what}: expected {expected} entries, got {got}")]
    LengthMismatch {
        what: &'static str,
        expected: usize,
        got: usize,
    },
    /// Too few landmark pairs for the requested fit.
    #[error("{needed} landmark pairs are needed for {purpose}, only {got} given ({names})")]
    TooFewLandmarks {
        needed: usize,
        got: usize,
        purpose: &'static str,
        names: String,
    },
    /// The same name occurs twice in one landmark list.
    #[error("landmark '{name}' is given twice in the {side} landmarks; remove one")]
    DuplicateName { name: String, side: &'static str },
    /// A coordinate is NaN or infinite.
    #[error("{side} landmark '{name}' has a non-finite coordinate ({x}, {y}, {z})")]
    NonFinite {
        name: String,
        side: &'static str,
        x: f64,
        y: f64,
        z: f64,
    },
    /// Two source landmarks sit at the same place: the interpolation matrix has two equal rows.
    #[error(
        "{side} landmarks '{first}' and '{second}' coincide (distance {distance:e}); \
         the RBF system is singular — drop one of them or set lambda > 0"
    )]
    CoincidentLandmarks {
        first: String,
        second: String,
        distance: f64,
        side: &'static str,
    },
    /// All landmarks lie on a line or a plane, so the affine term (or Procrustes) is undetermined.
    #[error(
        "the {side} landmarks are {shape} (spread ratio {ratio:e}), so {purpose} is undetermined; \
         landmarks: {names}"
    )]
    Degenerate {
        side: &'static str,
        shape: &'static str,
        ratio: f64,
        purpose: &'static str,
        names: String,
    },
    /// LU found a (numerically) singular or badly conditioned system.
    #[error(
        "the RBF system is ill-conditioned (reciprocal condition {rcond:e} < {min_rcond:e}); \
         smallest pivot at landmark '{worst}'. Use a narrower kernel, set lambda > 0, or check \
         landmarks near '{worst}'"
    )]
    IllConditioned {
        rcond: f64,
        min_rcond: f64,
        worst: String,
    },
    /// A kernel parameter is out of range.
    #[error("kernel parameter {name} = {value} is invalid: {reason}")]
    BadParameter {
        name: &'static str,
        value: f64,
        reason: &'static str,
    },
}

/// Lists names for an error message, shortening long lists.
pub(crate) fn name_list<S: AsRef<str>>(names: &[S]) -> String {
    const SHOWN: usize = 8;
    let mut text: Vec<&str> = names.iter().take(SHOWN).map(|n| n.as_ref()).collect();
    let more = names.len().saturating_sub(SHOWN);
    let more_text = format!("… and {more} more");
    if more > 0 {
        text.push(&more_text);
    }
    text.join(", ")
}
