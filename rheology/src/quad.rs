//! Gauss–Legendre rules, computed once and cached.

use std::sync::OnceLock;

/// Largest number of Gauss–Legendre points per panel that is cached.
pub(crate) const MAX_GL: usize = 24;

/// The n-point Gauss–Legendre rule on [-1, 1] (n clamped to 1..=MAX_GL),
/// computed on first use of that n (each rule separately, so a first call
/// that needs one rule does not pay for all of them).
pub(crate) fn rule(n: usize) -> &'static [(f64, f64)] {
    static T: [OnceLock<Vec<(f64, f64)>>; MAX_GL + 1] = [const { OnceLock::new() }; MAX_GL + 1];
    let n = n.clamp(1, MAX_GL);
    T[n].get_or_init(|| gauss_legendre(n))
}

/// Newton iteration on the Legendre polynomial P_n (three-term recurrence).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(n);
    if n == 0 {
        return out;
    }
    let nf = n as f64;
    for i in 0..n {
        // Chebyshev-like initial guess for the i-th root (descending).
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0_f64, x);
            for j in 2..=n {
                let jf = j as f64;
                let p2 = ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 1 { x } else { p1 };
            let pm = if n == 1 { 1.0 } else { p0 };
            dp = nf * (x * pn - pm) / (x * x - 1.0);
            let dx = pn / dp;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        out.push((x, w));
    }
    out.reverse();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_integrate_polynomials_exactly() {
        // An n-point rule is exact for degree 2n-1; compare with the exact
        // integral of x^d over [-1, 1] to 1e-14 (round-off of ~n terms).
        for n in 1..=MAX_GL {
            let r = rule(n);
            assert_eq!(r.len(), n);
            for d in 0..(2 * n) {
                let num: f64 = r.iter().map(|&(x, w)| w * x.powi(d as i32)).sum();
                let exact = if d % 2 == 1 {
                    0.0
                } else {
                    2.0 / (d as f64 + 1.0)
                };
                assert!((num - exact).abs() < 1e-14, "n={n} d={d} {num} {exact}");
            }
        }
    }
}
