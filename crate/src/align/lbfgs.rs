//! Limited-memory BFGS (Nocedal & Wright, *Numerical Optimization*, Alg. 7.4/7.5), allocation-free
//! after construction.
//!
//! Hand-written rather than `argmin` because the inner problem has two things a generic solver
//! cannot use: the exact curvature dᵀHd of the quadratic energy, which gives the exact line-search
//! step α = −gᵀd / dᵀHd at the price of one evaluation, and a per-vertex block preconditioner as
//! H₀. Both keep one energy evaluation per iteration, and the buffers are reused across rounds
//! (argmin's state moves own `Vec`s through every iteration, i.e. 12·#V-sized copies).
//! Without curvature information it falls back to Armijo backtracking from α = 1.

/// A smooth function to minimise.
pub trait Objective {
    /// f(x); writes ∇f(x) into `grad`.
    fn value_and_gradient(&mut self, x: &[f64], grad: &mut [f64]) -> f64;
    /// dᵀ∇²f d when cheaply known (exact for quadratics); `None` → backtracking.
    fn curvature(&self, _d: &[f64]) -> Option<f64> {
        None
    }
    /// Applies an initial inverse-Hessian approximation H₀ to `q` in place; `false` when there is
    /// none (then H₀ = γI with γ = sᵀy / yᵀy from the newest pair).
    fn precondition(&self, _q: &mut [f64]) -> bool {
        false
    }
}

/// What one [`Lbfgs::step`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Step {
    /// A point with lower f was accepted.
    Improved,
    /// No descent possible (zero gradient or line search failed): the iterate is unchanged.
    Stalled,
}

/// L-BFGS state: the current iterate, its value and gradient, and the last m correction pairs.
#[derive(Debug, Clone)]
pub struct Lbfgs {
    x: Vec<f64>,
    g: Vec<f64>,
    f: f64,
    s: Vec<Vec<f64>>,
    y: Vec<Vec<f64>>,
    rho: Vec<f64>,
    coef: Vec<f64>,
    len: usize,
    head: usize,
    d: Vec<f64>,
    x_trial: Vec<f64>,
    g_trial: Vec<f64>,
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl Lbfgs {
    /// Starts at `x0` with memory `m` (pairs kept); evaluate with [`Lbfgs::restart`] before stepping.
    pub fn new(x0: Vec<f64>, m: usize) -> Self {
        let n = x0.len();
        let m = m.max(1);
        Self {
            g: vec![0.0; n],
            f: f64::INFINITY,
            s: vec![vec![0.0; n]; m],
            y: vec![vec![0.0; n]; m],
            rho: vec![0.0; m],
            coef: vec![0.0; m],
            len: 0,
            head: 0,
            d: vec![0.0; n],
            x_trial: vec![0.0; n],
            g_trial: vec![0.0; n],
            x: x0,
        }
    }

    /// Current iterate.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// f at the current iterate (∞ before the first [`Lbfgs::restart`]).
    pub fn value(&self) -> f64 {
        self.f
    }

    /// Gradient at the current iterate.
    pub fn gradient(&self) -> &[f64] {
        &self.g
    }

    /// Re-evaluates f and ∇f — call when the objective changed (new correspondences). With
    /// `forget`, the correction pairs are dropped too: do that when the Hessian changed (a new
    /// stiffness); new targets alone leave y = H s, and so the pairs, valid.
    pub fn restart(&mut self, objective: &mut dyn Objective, forget: bool) -> f64 {
        if forget {
            self.len = 0;
            self.head = 0;
        }
        self.f = objective.value_and_gradient(&self.x, &mut self.g);
        self.f
    }

    /// d = −H g by the two-loop recursion.
    fn direction(&mut self, objective: &dyn Objective) {
        let m = self.s.len();
        self.d.copy_from_slice(&self.g);
        for k in 0..self.len {
            let idx = (self.head + m - 1 - k) % m;
            let a = self.rho[idx] * dot(&self.s[idx], &self.d);
            self.coef[idx] = a;
            self.d
                .iter_mut()
                .zip(&self.y[idx])
                .for_each(|(q, y)| *q -= a * y);
        }
        if !objective.precondition(&mut self.d) && self.len > 0 {
            let newest = (self.head + m - 1) % m;
            let yy = dot(&self.y[newest], &self.y[newest]);
            let gamma = if yy > 0.0 {
                1.0 / (self.rho[newest] * yy)
            } else {
                1.0
            };
            self.d.iter_mut().for_each(|q| *q *= gamma);
        }
        for k in (0..self.len).rev() {
            let idx = (self.head + m - 1 - k) % m;
            let b = self.rho[idx] * dot(&self.y[idx], &self.d);
            let c = self.coef[idx] - b;
            self.d
                .iter_mut()
                .zip(&self.s[idx])
                .for_each(|(r, s)| *r += c * s);
        }
        self.d.iter_mut().for_each(|r| *r = -*r);
    }

    /// One iteration: direction, line search, memory update.
    pub fn step(&mut self, objective: &mut dyn Objective) -> Step {
        self.direction(objective);
        let mut gd = dot(&self.g, &self.d);
        if gd >= 0.0 || gd.is_nan() {
            // Stale memory gave no descent direction: fall back to (preconditioned) steepest descent.
            self.len = 0;
            self.direction(objective);
            gd = dot(&self.g, &self.d);
            if gd >= 0.0 || gd.is_nan() {
                return Step::Stalled;
            }
        }
        let mut alpha = match objective.curvature(&self.d) {
            Some(c) if c > 0.0 && c.is_finite() => -gd / c,
            _ if self.len == 0 => 1.0 / dot(&self.d, &self.d).sqrt().max(1.0),
            _ => 1.0,
        };
        const ARMIJO: f64 = 1e-4;
        let mut accepted = None;
        for _ in 0..40 {
            for ((t, x), d) in self.x_trial.iter_mut().zip(&self.x).zip(&self.d) {
                *t = x + alpha * d;
            }
            let f = objective.value_and_gradient(&self.x_trial, &mut self.g_trial);
            if f.is_finite() && f <= self.f + ARMIJO * alpha * gd {
                accepted = Some(f);
                break;
            }
            alpha *= 0.5;
        }
        let Some(f_new) = accepted else {
            return Step::Stalled;
        };
        let m = self.s.len();
        let slot = self.head;
        let (s, y) = (&mut self.s[slot], &mut self.y[slot]);
        for k in 0..s.len() {
            s[k] = self.x_trial[k] - self.x[k];
            y[k] = self.g_trial[k] - self.g[k];
        }
        let sy = dot(s, y);
        if sy > 1e-300 {
            self.rho[slot] = 1.0 / sy;
            self.head = (self.head + 1) % m;
            self.len = (self.len + 1).min(m);
        }
        std::mem::swap(&mut self.x, &mut self.x_trial);
        std::mem::swap(&mut self.g, &mut self.g_trial);
        self.f = f_new;
        Step::Improved
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock in 2-D: minimum 0 at (1, 1).
    struct Rosenbrock;
    impl Objective for Rosenbrock {
        fn value_and_gradient(&mut self, x: &[f64], g: &mut [f64]) -> f64 {
            let (a, b) = (x[0], x[1]);
            g[0] = -2.0 * (1.0 - a) - 400.0 * a * (b - a * a);
            g[1] = 200.0 * (b - a * a);
            (1.0 - a).powi(2) + 100.0 * (b - a * a).powi(2)
        }
    }

    #[test]
    fn minimises_rosenbrock_with_backtracking() {
        let mut opt = Lbfgs::new(vec![-1.2, 1.0], 5);
        opt.restart(&mut Rosenbrock, true);
        for _ in 0..500 {
            if opt.step(&mut Rosenbrock) == Step::Stalled {
                break;
            }
        }
        assert!(opt.value() < 1e-10, "f = {}", opt.value());
        assert!((opt.x()[0] - 1.0).abs() < 1e-4 && (opt.x()[1] - 1.0).abs() < 1e-4);
    }

    /// f = ½ xᵀ diag(1..n) x with exact curvature: the exact line search solves it in ≤ n steps.
    struct Diagonal;
    impl Objective for Diagonal {
        fn value_and_gradient(&mut self, x: &[f64], g: &mut [f64]) -> f64 {
            let mut f = 0.0;
            for (k, (xi, gi)) in x.iter().zip(g.iter_mut()).enumerate() {
                *gi = (k + 1) as f64 * xi;
                f += 0.5 * (k + 1) as f64 * xi * xi;
            }
            f
        }
        fn curvature(&self, d: &[f64]) -> Option<f64> {
            Some(
                d.iter()
                    .enumerate()
                    .map(|(k, v)| (k + 1) as f64 * v * v)
                    .sum(),
            )
        }
    }

    #[test]
    fn exact_line_search_solves_quadratic() {
        let mut opt = Lbfgs::new(vec![1.0; 6], 10);
        opt.restart(&mut Diagonal, true);
        for _ in 0..12 {
            if opt.step(&mut Diagonal) == Step::Stalled {
                break;
            }
        }
        assert!(opt.value() < 1e-16, "f = {}", opt.value());
    }
}
