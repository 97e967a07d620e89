//! Quantiles of the standard normal and χ² distributions: where a share p of a normal population
//! lies inside (outlier thresholds, [`super::outliers`]; coverage ellipsoids,
//! [`super::boundary_manikins`]).

/// The standard normal quantile Φ⁻¹(p) for p in (0, 1): Acklam's rational approximation
/// (relative error < 1.2·10⁻⁹), refined by one Halley step on erfc. NaN outside (0, 1).
pub fn normal_quantile(p: f64) -> f64 {
    if !(p > 0.0 && p < 1.0) {
        return f64::NAN;
    }
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    const LOW: f64 = 0.02425;
    if p < LOW {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - LOW {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

/// The χ² quantile with `k` degrees of freedom: the x with P(χ²ₖ ≤ x) = p, for p in (0, 1).
/// Starts from the Wilson–Hilferty approximation k·(1 − 2/(9k) + z·√(2/(9k)))³, z = Φ⁻¹(p)
/// (within 1 % from k = 3 up), then Newton steps on the regularised lower incomplete gamma
/// function P(k/2, x/2) bring it to 10⁻¹⁰ relative. NaN for k = 0 or p outside (0, 1).
pub fn chi_square_quantile(k: usize, p: f64) -> f64 {
    if k == 0 || !(p > 0.0 && p < 1.0) {
        return f64::NAN;
    }
    let kf = k as f64;
    let a = 2.0 / (9.0 * kf);
    let mut x = (kf * (1.0 - a + normal_quantile(p) * a.sqrt()).powi(3)).max(1e-8 * kf);
    let half = kf / 2.0;
    let log_gamma_half = ln_gamma(half);
    for _ in 0..50 {
        // The χ²ₖ density at x: x^(k/2−1)·e^(−x/2) / (2^(k/2)·Γ(k/2)).
        let density =
            ((half - 1.0) * x.ln() - x / 2.0 - half * std::f64::consts::LN_2 - log_gamma_half)
                .exp();
        let step = (lower_gamma_regularised(half, x / 2.0) - p) / density;
        let next = (x - step).max(x / 10.0);
        let done = (next - x).abs() <= 1e-12 * x;
        x = next;
        if done {
            break;
        }
    }
    x
}

/// ln Γ(a) for a > 0 (Lanczos, g = 7, 9 terms; ~15 digits).
fn ln_gamma(a: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if a < 0.5 {
        let pi = std::f64::consts::PI;
        return (pi / (pi * a).sin()).ln() - ln_gamma(1.0 - a);
    }
    let a = a - 1.0;
    let t = a + 7.5;
    let sum = G[1..]
        .iter()
        .enumerate()
        .fold(G[0], |s, (i, g)| s + g / (a + i as f64 + 1.0));
    0.5 * (2.0 * std::f64::consts::PI).ln() + (a + 0.5) * t.ln() - t + sum.ln()
}

/// P(a, x) = γ(a, x)/Γ(a): the series below x < a + 1, the continued fraction of Q = 1 − P
/// above (Numerical Recipes §6.2).
fn lower_gamma_regularised(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    let front = (a * x.ln() - x - ln_gamma(a)).exp();
    if x < a + 1.0 {
        let (mut term, mut sum, mut n) = (1.0 / a, 1.0 / a, a);
        for _ in 0..500 {
            n += 1.0;
            term *= x / n;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        sum * front
    } else {
        // Modified Lentz.
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..500 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            d = if d.abs() < tiny { tiny } else { d };
            c = b + an / c;
            c = if c.abs() < tiny { tiny } else { c };
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        1.0 - front * h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantiles_are_the_tabulated_ones() {
        for (p, z) in [
            (0.5, 0.0),
            (0.9, 1.281_551_565_5),
            (0.95, 1.644_853_626_95),
            (0.975, 1.959_963_984_54),
            (0.999, 3.090_232_306_17),
            (0.001, -3.090_232_306_17),
            (1e-6, -4.753_424_308_82),
        ] {
            assert!((normal_quantile(p) - z).abs() < 1e-8, "p {p}");
        }
        assert!(normal_quantile(0.0).is_nan() && normal_quantile(1.0).is_nan());
    }

    #[test]
    fn chi_square_quantiles_are_the_tabulated_ones() {
        // Tables (e.g. NIST/SEMATECH 1.3.6.7.4) to 3 decimals, and the closed forms of k = 1, 2.
        for (k, p, q) in [
            (1, 0.95, 3.841),
            (2, 0.9, 4.605),
            (3, 0.9, 6.251),
            (4, 0.9, 7.779),
            (4, 0.95, 9.488),
            (10, 0.999, 29.588),
            (20, 0.999, 45.315),
            (3, 0.05, 0.352),
            (30, 0.5, 29.336),
        ] {
            let x = chi_square_quantile(k, p);
            assert!((x - q).abs() < 1e-3, "k {k} p {p}: {x} vs {q}");
        }
        for p in [0.5, 0.9, 0.99] {
            let x = chi_square_quantile(2, p);
            assert!((x + 2.0 * (1.0 - p).ln()).abs() < 1e-9, "k 2, p {p}: {x}");
            let z = normal_quantile(0.5 + p / 2.0);
            assert!(
                (chi_square_quantile(1, p) - z * z).abs() < 1e-7,
                "k 1, p {p}"
            );
        }
        assert!(chi_square_quantile(0, 0.9).is_nan());
        assert!(chi_square_quantile(3, 1.0).is_nan());
    }
}
