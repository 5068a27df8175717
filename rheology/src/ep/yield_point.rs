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
/// Largest number of safeguarded Halley/Newton steps (bisection guarantees
/// convergence well within it).
const NEWTON_ITERATIONS: usize = 100;
/// A first root this close to the outlet (relative to c) is the outlet
/// itself: the strip ends elastic ([`Strip::find_yield`] returns c exactly).
const OUTLET_GAP: f64 = 1e-15;

impl Strip {
    /// First X > x0 where the elastic stress from (x0, z0) reaches the limit.
    ///
    /// With e = X − x0, f = |Z|² − L² = f(x0) + e·g(e) where g is the cubic
    /// p1 + p2·e + p3·e² + p4·e³ (Z is quadratic in e, L² quadratic in X).
    /// f(x0) = 0 (the inlet, or the limit where unloading began), so the
    /// first crossing is the first sign change of g: g is monotone between
    /// the roots of the quadratic g', so f is evaluated at those points and at
    /// the outlet (where f = |Z|² ≥ 0), and the first bracket with f ≥ 0 at
    /// its end holds exactly one crossing. Its first iterate is the root of
    /// the quadratic through g at both ends that is flat at a turning-point
    /// end (false position where neither end is one), improved by two
    /// unguarded Halley steps on g (Horner in e, no bracket bookkeeping;
    /// a step leaving the bracket is dropped); then safeguarded Halley on f
    /// (`Strip::refine`), which then mostly stops after one evaluation
    /// (docs/decisions/0089).
    ///
    /// The iteration stops once the error left by its last step,
    /// ≈ |3f''² − 2f'·f'''|/(12f'²)·d³ for Halley's step (d = f/f'; cubic
    /// convergence), ≈ |f''/2f'|·d² for a Newton step (quadratic; f'' is
    /// large at high spin, up to ≈ 1e5 relative to f'), is below
    /// 1e-3·s_step⁴ of max(c, |X|): the plastic steps' RK4 error is
    /// ≈ 10·s_step⁴ (the tolerance, `Accuracy::s_step`), so the root is
    /// resolved 1e4 times finer than the strip sums need (they change by
    /// ≈ |Z|·δX).
    ///
    /// Where the first crossing lies within [`OUTLET_GAP`]·c of the outlet,
    /// c is returned exactly (the strip ends elastic), decided on the
    /// closed-form f at c·(1 − OUTLET_GAP) before any iteration (L² there
    /// without cancellation); otherwise the bracket ends there. A root at
    /// the outlet (Z(c) = 0, as on the spin pole's strip without side slip,
    /// where f = (c² − X²)·(q2²·(c² − X²)/4 − 9/4)) is where the quartic's
    /// coefficients' form is least precise (its terms, up to |p4|·(2c)⁴,
    /// cancel to 0 there, leaving a round-off of several times the
    /// convergence test on |f|): the iterate landed on either side of the
    /// old threshold c·(1 − 1e-15) at random, and the strip's flow topology,
    /// which gates the panels' accuracy test, with it (docs/decisions/0089).
    pub(super) fn find_yield(&self, x0: f64, z0: (f64, f64), s_step: f64) -> f64 {
        crate::counts::count!(yield_searches);
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
        // g at the bracket's low end (for the first iterate).
        let (mut lo, mut glo) = (x0, p1);
        for &e in &pts[..=n] {
            let xj = if e >= span { c } else { x0 + e };
            if xj <= x0 + eps && xj < c {
                continue;
            }
            let ej = xj - x0;
            let gj = p1 + ej * (p2 + ej * (p3 + ej * p4));
            let f = p0 + ej * gj;
            if f >= 0.0 || f.is_nan() {
                let mut hi = xj;
                if e >= span {
                    // The outlet, where L = 0: the crossing is within the
                    // gap of it (f ≤ 0 at its start; c − xt and L² there
                    // without cancellation), else below it.
                    let xt = c - OUTLET_GAP * c;
                    if xt > lo {
                        let z = self.z_el(x0, z0, xt);
                        if z.0 * z.0 + z.1 * z.1 <= 2.25 * (c - xt) * (c + xt) {
                            return c;
                        }
                        hi = xt;
                    }
                }
                let start = if glo < 0.0 && gj > glo {
                    // g' = 0 at a bracket end that is a turning point: g is
                    // near-quadratic there, so the root of the quadratic
                    // through both ends, flat at that end (where both are,
                    // the end with the smaller |g|), starts closer than false
                    // position, which misplaces it towards the flat end.
                    let w = xj - lo;
                    let dg = gj - glo;
                    if e < span && (lo <= x0 || gj <= -glo) {
                        xj - w * (gj / dg).sqrt()
                    } else if lo > x0 {
                        lo + w * (-glo / dg).sqrt()
                    } else {
                        lo - w * glo / dg
                    }
                } else {
                    xj
                };
                // Two unguarded Halley steps on the cubic g (cheap: no
                // bracket bookkeeping), kept only while inside the bracket.
                let mut start = start;
                for _ in 0..2 {
                    let e = start - x0;
                    let g = p1 + e * (p2 + e * (p3 + e * p4));
                    let gp = p2 + e * (2.0 * p3 + e * 3.0 * p4);
                    let gpp = 2.0 * p3 + e * 6.0 * p4;
                    // Halley's d/(1 − d·g''/(2g')), d = g/g', as one
                    // division; Newton's step where that denominator is
                    // below 1/2.
                    let gp2 = gp * gp;
                    let q = 2.0 * gp2 - g * gpp;
                    let xn = start - if q >= gp2 { 2.0 * g * gp / q } else { g / gp };
                    if xn > lo && xn < xj {
                        start = xn;
                    } else {
                        break;
                    }
                }
                // A crossing within rounding of the bracket's low end: the
                // start and its Halley steps land on it. This is the inlet
                // (or an unloading's end) at rates |v| ≳ 1e8, where the
                // elastic segment, ≈ 4.5·c/|v|², is shorter than an ulp of
                // X. The next float above it is the crossing to round-off
                // (the strip sums change by ≈ |v|·δX² there); from the
                // bracket's high end the iteration would approach it by
                // a third per step and stop early on its error estimate,
                // which holds only near a simple root (at |J1| = 1e10,
                // k = 0.07, δX = 4e-7·c: J4 off by 1.4·tol at tol 1e-3).
                if start <= lo {
                    let x1 = lo.next_up();
                    let e = x1 - x0;
                    if x1 < hi && p0 + e * (p1 + e * (p2 + e * (p3 + e * p4))) >= 0.0 {
                        return x1;
                    }
                }
                let s2 = s_step * s_step;
                let root_tol = ROOT_TOL_PER_STEP4 * s2 * s2;
                return self.refine(x0, [p0, p1, p2, p3, p4], lo, hi, start, root_tol);
            }
            (lo, glo) = (xj, gj);
        }
        c
    }

    /// Safeguarded Halley iteration for the first crossing f ≥ 0 in
    /// (lo, hi], from `start` (or hi if it is outside the bracket), on the
    /// quartic f = Σ p_k·e^k, e = X − x0 (Horner in e).
    ///
    /// Halley's step dx = d/(1 − d·f''/(2f')), d = f/f', leaves an error
    /// ≈ |3f''² − 2f'·f'''|/(12f'²)·|d|³ (cubic convergence); where its
    /// denominator is below 1/2 (far from the root) the Newton step is taken
    /// instead, whose error is ≈ |f''/(2f')|·d². Both with one division
    /// (Halley's as 2f·f'/(2f'² − f·f''), the error tests multiplied out):
    /// three divisions made the bench cases up to 4 % slower in wall time
    /// at the same instruction count (docs/decisions/0089).
    fn refine(
        &self,
        x0: f64,
        p: [f64; 5],
        mut lo: f64,
        mut hi: f64,
        start: f64,
        root_tol: f64,
    ) -> f64 {
        let ftol = F_TOL * (1.0 + 2.25 * self.c * self.c);
        let mut x = if start > lo && start < hi { start } else { hi };
        let (d2, d3, d4) = (2.0 * p[2], 3.0 * p[3], 4.0 * p[4]);
        let (s3, s4) = (6.0 * p[3], 12.0 * p[4]);
        let t4 = 24.0 * p[4];
        for _ in 0..NEWTON_ITERATIONS {
            let e = x - x0;
            let f = p[0] + e * (p[1] + e * (p[2] + e * (p[3] + e * p[4])));
            if f.abs() <= ftol {
                // Converged (from either side: the iteration often approaches
                // the root from below, where the bracket would not shrink).
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
            let fp = p[1] + e * (d2 + e * (d3 + e * d4));
            let fpp = d2 + e * (s3 + e * s4);
            // One division per step (Halley's d/(1 − d·f''/(2f')) as
            // 2f·f'/(2f'² − f·f''), its error estimate multiplied out).
            let fp2 = fp * fp;
            let q = 2.0 * fp2 - f * fpp;
            let halley = q >= fp2;
            let xn = if halley {
                x - 2.0 * f * fp / q
            } else {
                x - f / fp
            };
            let inside = xn > lo && xn < hi && xn.is_finite();
            if inside {
                let scale = self.c.max(lo.abs());
                let f2 = f * f;
                let done = if halley {
                    let fppp = s3 + e * t4;
                    (3.0 * fpp * fpp - 2.0 * fp * fppp).abs() * (f2 * f.abs())
                        <= 12.0 * root_tol * scale * fp2 * fp2 * fp.abs()
                } else {
                    fpp.abs() * f2 <= 2.0 * root_tol * scale * fp2 * fp.abs()
                };
                if done {
                    return xn;
                }
            }
            x = if inside { xn } else { 0.5 * (lo + hi) };
        }
        hi
    }
}

#[cfg(test)]
mod tests {
    use super::super::Strip;

    /// f = |Z|² − L² from the closed-form stress (not the quartic's
    /// coefficients that `find_yield` iterates on).
    fn f_direct(s: &Strip, x0: f64, z0: (f64, f64), x: f64) -> f64 {
        let z = s.z_el(x0, z0, x);
        z.0 * z.0 + z.1 * z.1 - 2.25 * (s.c * s.c - x * x)
    }

    /// The first sign change of f after x0 by a scan of 20 000 points
    /// (graded as (i/n)³ towards x0, where yield comes early at high spin),
    /// then bisection to the last bit (independent of the bracketing and the
    /// iteration under test).
    fn first_root(s: &Strip, x0: f64, z0: (f64, f64)) -> f64 {
        let n = 20_000;
        let span = s.c - x0;
        let at = |i: usize| x0 + span * (i as f64 / n as f64).powi(3);
        let mut lo = at(1);
        for i in 2..=n {
            let hi = if i == n { s.c } else { at(i) };
            if f_direct(s, x0, z0, hi) >= 0.0 {
                let mut hi = hi;
                while hi - lo > 1e-16 * s.c.max(hi.abs()) {
                    let m = 0.5 * (lo + hi);
                    if m <= lo || m >= hi {
                        break;
                    }
                    if f_direct(s, x0, z0, m) >= 0.0 {
                        hi = m;
                    } else {
                        lo = m;
                    }
                }
                return hi;
            }
            lo = hi;
        }
        s.c
    }

    #[test]
    fn yield_point_matches_a_scan_and_bisection() {
        // Strips from no to high spin (q2 up to 400), from the inlet and from
        // a point on the limit where the stress unloads (|Z| = L, f' < 0).
        // s_step 0.1 (tol 1e-3) asks for 1e-3·0.1⁴ = 1e-7 of c; the
        // iteration's error estimate is asymptotic, so 1e-6·c is allowed
        // (the strip sums need ≈ 1e-4·c, docs/decisions/0089).
        let s_step = 0.1;
        let mut worst: f64 = 0.0;
        let mut count = 0;
        for &c in &[1.0, 0.6, 0.2, 0.03] {
            for &a in &[0.0, 0.3, 2.0, 10.0] {
                for &b1 in &[-5.0, -0.7, 0.0, 0.4, 3.0] {
                    for &q2 in &[0.0, -1.0, 6.0, -40.0, 400.0] {
                        let s = Strip {
                            c,
                            a,
                            b1,
                            q2,
                            gy: 1.0,
                            vis: None,
                        };
                        let mut starts = vec![(-c, (0.0, 0.0))];
                        // Unloading at X = −0.3c with the stress opposing
                        // the slip (so that |Z| falls below L at first).
                        let xu = -0.3 * c;
                        let l = 1.5 * (c * c - xu * xu).sqrt();
                        let (vx, vy) = (a, b1 + q2 * xu);
                        let m = (vx * vx + vy * vy).sqrt();
                        if m > 0.0 {
                            starts.push((xu, (-l * vx / m, -l * vy / m)));
                        }
                        for (x0, z0) in starts {
                            let x = s.find_yield(x0, z0, s_step);
                            let r = first_root(&s, x0, z0);
                            let err = (x - r).abs() / c;
                            assert!(
                                err <= 1e-6,
                                "c {c} a {a} b1 {b1} q2 {q2} x0 {x0}: {x} vs {r}"
                            );
                            worst = worst.max(err);
                            count += 1;
                        }
                    }
                }
            }
        }
        assert!(count > 700, "{count} cases");
        eprintln!("worst |X − X_ref|/c = {worst:.2e} over {count} cases");
    }

    #[test]
    fn a_strip_whose_stress_returns_to_zero_at_the_outlet_ends_elastic() {
        // The spin pole's strip without side slip (a = b1 = 0): Z = (0,
        // q2·(X² − c²)/2) returns to 0 at the outlet and f = (c² − X²)·
        // (q2²·(c² − X²)/4 − 9/4) < 0 inside when |q2|·c < 3, so the first
        // root is c itself: exactly c, every time. Without the outlet test
        // the iteration on the quartic's coefficients missed c in 838 of
        // these 4000 strips, in 329 of them by more than the former
        // ends-elastic threshold 1e-15·c (the strip's flow topology then
        // flips). Beyond |q2|·c = 3 it yields inside, at c² − X² = 9/q2²
        // (within the 1e-6·c of the test above).
        let pole_strip = |c: f64, q2: f64| Strip {
            c,
            a: 0.0,
            b1: 0.0,
            q2,
            gy: 1.0,
            vis: None,
        };
        let mut n = 0;
        for i in 0..1000 {
            let c = 0.05 + 0.95 * f64::from(i) / 999.0;
            for r in [0.3, 1.7, 2.9, -2.2] {
                let q2 = r / c;
                let x = pole_strip(c, q2).find_yield(-c, (0.0, 0.0), 0.1);
                assert!(x == c, "c {c} q2 {q2}: {x:e}");
                n += 1;
            }
        }
        assert_eq!(n, 4000);
        for r in [3.5, -6.0, 40.0] {
            let (c, q2) = (0.8, r / 0.8);
            let x = pole_strip(c, q2).find_yield(-c, (0.0, 0.0), 0.1);
            let exact = -(c * c - 9.0 / (q2 * q2)).sqrt();
            assert!((x - exact).abs() <= 1e-6 * c, "q2 {q2}: {x} vs {exact}");
        }
    }
}
