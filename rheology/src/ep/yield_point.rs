//! The elastic → plastic transition of a strip: the first root of the
//! quartic |Z(X)|² − L(X)² along an elastic segment.

use super::Strip;

/// Bracket points closer than this (relative to c) to the segment start are
/// skipped (f = 0 there by construction).
const BRACKET_EPS: f64 = 1e-13;
/// |f| = ||Z|² − L²| counted as converged, relative to 1 + L(0)².
const F_TOL: f64 = 1e-15;
/// Bracket width in X counted as converged, relative to max(c, |X|).
const X_TOL: f64 = 4e-16;
/// Root error (relative to max(c, |X|)) accepted per s-step⁴, see
/// [`Strip::find_yield`].
const ROOT_TOL_PER_STEP4: f64 = 1e-3;
/// Largest number of safeguarded Newton steps (bisection guarantees
/// convergence well within it).
const NEWTON_ITERATIONS: usize = 100;

impl Strip {
    /// First X > x0 where the elastic stress from (x0, z0) reaches the limit.
    ///
    /// With e = X − x0, f = |Z|² − L² = f(x0) + e·g(e) where g is the cubic
    /// p1 + p2·e + p3·e² + p4·e³ (Z is quadratic in e, L² quadratic in X).
    /// f(x0) = 0 (the inlet, or the limit where unloading began), so the
    /// first crossing is the first sign change of g: g is monotone between
    /// the roots of the quadratic g', so f is evaluated at those points and at
    /// the outlet (where f = |Z|² ≥ 0), and the first bracket with f ≥ 0 at
    /// its end holds exactly one crossing, refined by safeguarded Newton.
    ///
    /// Newton stops once the error left by its last step, ≈ |f''/2f'|·step²
    /// (quadratic convergence; f'' = 2(a² + vy² + Zy·q2) + 4.5 is large at
    /// high spin, up to ≈ 1e5 relative to f'), is below 1e-3·s_step⁴ of
    /// max(c, |X|): the plastic steps' RK4 error is ≈ 10·s_step⁴ (the
    /// tolerance, `Accuracy::s_step`), so the root is resolved 1e4 times
    /// finer than the strip sums need (they change by ≈ |Z|·δX).
    pub(super) fn find_yield(&self, x0: f64, z0: (f64, f64), s_step: f64) -> f64 {
        let c = self.c;
        let span = c - x0;
        if span <= 0.0 {
            return c;
        }
        let b = self.vy(x0);
        let q = self.q2;
        let p2 = self.a * self.a + b * b + z0.1 * q + 2.25;
        let p3 = b * q;
        let p4 = 0.25 * q * q;
        // Roots of g'(e) = p2 + 2·p3·e + 3·p4·e² inside (0, span).
        let mut pts = [span; 3];
        let (qa, qb, qc) = (3.0 * p4, 2.0 * p3, p2);
        let (mut r1, mut r2) = (f64::NAN, f64::NAN);
        if qa != 0.0 {
            let disc = qb * qb - 4.0 * qa * qc;
            if disc >= 0.0 {
                let t = -0.5 * (qb + qb.signum() * disc.sqrt());
                r1 = t / qa;
                r2 = if t != 0.0 { qc / t } else { -r1 };
            }
        } else if qb != 0.0 {
            r1 = -qc / qb;
        }
        if r1 > r2 {
            std::mem::swap(&mut r1, &mut r2);
        }
        let mut n = 0;
        for r in [r1, r2] {
            if r > 0.0 && r < span {
                pts[n] = r;
                n += 1;
            }
        }
        let eps = BRACKET_EPS * c;
        let p1 = 2.0 * (z0.0 * self.a + z0.1 * b) + 4.5 * x0;
        let p0 = z0.0 * z0.0 + z0.1 * z0.1 - 2.25 * (c * c - x0 * x0);
        // g at the bracket's low end (for the false-position start).
        let (mut lo, mut glo) = (x0, p1);
        for &e in &pts[..=n] {
            let xj = if e >= span { c } else { x0 + e };
            if xj <= x0 + eps && xj < c {
                continue;
            }
            let (f, _) = self.f_el(x0, z0, xj);
            let gj = (f - p0) / (xj - x0);
            if f >= 0.0 || f.is_nan() {
                let start = if glo < 0.0 && gj > glo {
                    lo + (xj - lo) * glo / (glo - gj)
                } else {
                    xj
                };
                let s2 = s_step * s_step;
                let root_tol = ROOT_TOL_PER_STEP4 * s2 * s2;
                return self.refine(x0, z0, lo, xj, start, root_tol);
            }
            (lo, glo) = (xj, gj);
        }
        c
    }

    /// Safeguarded Newton for the first crossing f ≥ 0 in (lo, hi], from
    /// `start` (or hi if it is outside the bracket).
    fn refine(
        &self,
        x0: f64,
        z0: (f64, f64),
        mut lo: f64,
        mut hi: f64,
        start: f64,
        root_tol: f64,
    ) -> f64 {
        let ftol = F_TOL * (1.0 + 2.25 * self.c * self.c);
        let mut x = if start > lo && start < hi { start } else { hi };
        for _ in 0..NEWTON_ITERATIONS {
            let (f, fp) = self.f_el(x0, z0, x);
            if f.abs() <= ftol {
                // Converged (from either side: Newton often approaches the
                // root from below, where the bracket would not shrink).
                return x;
            }
            if f >= 0.0 || f.is_nan() {
                hi = x;
            } else {
                lo = x;
            }
            if hi - lo <= X_TOL * self.c.max(lo.abs()) {
                return hi;
            }
            let dx = f / fp;
            let xn = x - dx;
            let inside = xn > lo && xn < hi && xn.is_finite();
            if inside {
                let vy = self.vy(x);
                let e = x - x0;
                let zy = z0.1 + (self.b1 + self.q2 * x0) * e + 0.5 * self.q2 * e * e;
                let fpp = 2.0 * (self.a * self.a + vy * vy + zy * self.q2) + 4.5;
                let scale = self.c.max(lo.abs());
                if (fpp * dx * dx).abs() <= 2.0 * root_tol * scale * fp.abs() {
                    return xn;
                }
            }
            x = if inside { xn } else { 0.5 * (lo + hi) };
        }
        hi
    }
}
