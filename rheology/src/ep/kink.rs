//! A strip's kink margin: a number, continuous in Y, that changes sign
//! where the strip sums have a kink because an unloading appears or
//! vanishes (the flow-topology changes that the adaptive panels in Y chase
//! next to the spin pole's strip, docs/decisions/0086), so that such a kink
//! can be located by regula falsi from strips already computed
//! (`quadrature::lobatto_kronrod_in_phi`, docs/decisions/0094).
//!
//! * A strip without unloading has a margin ≥ 0: the smallest of g =
//!   (v·n)·cos s + (3/2)·sin s over its plastic segments (g < 0 starts an
//!   unloading; between step ends the minimum of g's cubic Hermite
//!   interpolant from g and dg/ds), of L − |Z| at the interior minima of
//!   L² − |Z|² on its elastic segments (where a plastic segment appears by
//!   tangency), and of [`MARGIN_CAP`].
//! * A strip with an unloading has a margin < 0: the above, and for each
//!   unloading g'(s_u)·ℓ/6, with g'(s_u) < 0 the slope of g where it
//!   starts and ℓ the shorter of the elastic segment that follows and the
//!   plastic segment before it (in s). Where g dips below 0 like
//!   g_min + g''·(s − s0)²/2 the unloaded segment is 1.5 times as long as
//!   the interval with g < 0 (|Z| − L ≈ ∫g ds returns to 0 there), so
//!   g'(s_u)·ℓ/6 is the dip's g_min: the margin continues the smallest g of
//!   the strips that stay plastic. Where the plastic segment before the
//!   unloading is the shorter (it appeared by tangency of |Z| with L, and
//!   the unloading at once), ℓ is its length, which vanishes at that kink.
//!
//! Both sides go to 0 at a kink of either kind, so the margin is continuous
//! across it, about linear in Y within ~1/|J3| of it (beyond, the margin of
//! the plastic side levels off at g's value at the outlet, 3/2).

use super::{Event, Strip, StripSums};

/// Largest margin: g at the outlet (s = π/2), where every plastic segment
/// ends; also the margin of a strip that stays elastic and nowhere nears
/// the limit.
pub(super) const MARGIN_CAP: f64 = 1.5;

/// Equal intervals per elastic segment on which the sign of d(L² − |Z|²)/dX
/// (a cubic in X) is sampled for its interior minima.
const ELASTIC_SAMPLES: usize = 12;

/// Bisections of a sampled interval on which d(L² − |Z|²)/dX changes sign
/// from − to + (2⁻⁴⁰ of it: the minimum's value to round-off).
const ELASTIC_BISECTIONS: usize = 40;

impl Strip {
    /// [`Strip::integrate_etd`] with the strip's kink margin
    /// (module docs): the sums, the flow topology, the margin and the
    /// unloading amplitude.
    pub(crate) fn integrate_etd_margin(
        &self,
        s_step: f64,
        s_step_smooth: f64,
        etd_step: f64,
    ) -> (StripSums, u32, f64, f64) {
        let c = self.c;
        // sin s, g and dg/ds at the previous plastic state of the segment.
        let mut prev: Option<(f64, f64, f64)> = None;
        // sin s at the segment's yield point.
        let mut yield_sn = 0.0;
        let mut m = MARGIN_CAP;
        let steps = (s_step, s_step_smooth, etd_step, true);
        let (sums, topology, amplitude) = self.integrate_with(steps, &mut |e| match e {
            Event::Plastic { x, n } => {
                let sn = (x / c).clamp(-1.0, 1.0);
                let cs = (1.0 - sn * sn).max(0.0).sqrt();
                let g = self.g::<false>(sn, cs, n.0, n.1);
                let d = self.g_rate::<false>(sn, cs, n.0, n.1);
                m = m.min(g.max(0.0));
                match prev {
                    None => yield_sn = sn,
                    Some((sn0, g0, d0)) if d0 < 0.0 && d > 0.0 => {
                        let h = sn.asin() - sn0.asin();
                        m = m.min(hermite_min(g0, d0 * h, g, d * h).max(0.0));
                    }
                    Some(_) => {}
                }
                prev = Some((sn, g, d));
            }
            Event::Elastic { x0, z0, x1 } => {
                // An unloading: the elastic segment follows a plastic state.
                if let Some((sn0, _, d0)) = prev {
                    if d0 < 0.0 {
                        let s0 = sn0.asin();
                        let elastic = (x1 / c).clamp(-1.0, 1.0).asin() - s0;
                        let plastic = s0 - yield_sn.asin();
                        m = m.min(d0 * elastic.min(plastic) / 6.0);
                    } else {
                        m = m.min(0.0);
                    }
                }
                prev = None;
                m = m.min(self.elastic_margin(x0, z0, x1));
            }
        });
        (sums, topology, m, amplitude)
    }

    /// The smallest L − |Z| at the interior minima of L² − |Z|² on the
    /// elastic segment from x0 (stress z0) to x1 (≥ 0; [`MARGIN_CAP`] if it
    /// has none).
    fn elastic_margin(&self, x0: f64, z0: (f64, f64), x1: f64) -> f64 {
        let len = x1 - x0;
        let mut m = MARGIN_CAP;
        if len.is_nan() || len <= 0.0 {
            return m;
        }
        let b = self.vy(x0);
        let z = |e: f64| (z0.0 + self.a * e, z0.1 + b * e + 0.5 * self.q2 * e * e);
        // d(L² − |Z|²)/dX with L² = (9/4)(c² − X²).
        let dq = |e: f64| {
            let (zx, zy) = z(e);
            -4.5 * (x0 + e) - 2.0 * zx * self.a - 2.0 * zy * (b + self.q2 * e)
        };
        let mut el = 0.0;
        let mut dl = dq(0.0);
        for j in 1..=ELASTIC_SAMPLES {
            let er = len * j as f64 / ELASTIC_SAMPLES as f64;
            let dr = dq(er);
            if dl < 0.0 && dr > 0.0 {
                let (mut lo, mut hi) = (el, er);
                for _ in 0..ELASTIC_BISECTIONS {
                    let mid = 0.5 * (lo + hi);
                    if dq(mid) < 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let e = 0.5 * (lo + hi);
                let x = x0 + e;
                let (zx, zy) = z(e);
                let l = 1.5 * (self.c * self.c - x * x).max(0.0).sqrt();
                m = m.min((l - zx.hypot(zy)).max(0.0));
            }
            el = er;
            dl = dr;
        }
        m
    }
}

/// The minimum on (0, 1) of the cubic Hermite interpolant with values g0,
/// g1 and derivatives d0 < 0 < d1 (per unit interval) at 0 and 1.
fn hermite_min(g0: f64, d0: f64, g1: f64, d1: f64) -> f64 {
    // G(u) = g0 + d0·u + c2·u² + c3·u³, G'(u) = d0 + 2·c2·u + 3·c3·u².
    let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let c3 = 2.0 * (g0 - g1) + d0 + d1;
    let u = if c3.abs() <= 1e-14 * (c2.abs() + d0.abs()) {
        -d0 / (2.0 * c2)
    } else {
        // The root of G' where G'' = 2·c2 + 6·c3·u > 0: G' goes from
        // d0 < 0 to d1 > 0, so it has exactly one such root in (0, 1).
        let disc = (c2 * c2 - 3.0 * c3 * d0).max(0.0).sqrt();
        let r = [(-c2 + disc) / (3.0 * c3), (-c2 - disc) / (3.0 * c3)];
        let ok = |r: f64| r > 0.0 && r < 1.0 && c2 + 3.0 * c3 * r >= 0.0;
        r.into_iter().find(|&r| ok(r)).unwrap_or(f64::NAN)
    };
    if u.is_finite() {
        g0 + u * (d0 + u * (c2 + u * c3))
    } else {
        g0.min(g1)
    }
}

#[cfg(test)]
mod tests {
    use super::hermite_min;
    use crate::ep::Scaled;

    #[test]
    fn unloading_amplitude_vanishes_at_the_kink() {
        // k = 0.0767, J = (−0.0595, −0.0924, −0.319): the strips lose their
        // unloading at φ ≈ 0.5176 (topology 2 → 0, the strip sums' kink).
        // The amplitude (`Strip::integrate_etd`) falls towards it
        // like the margin's unloading term, and is +∞ beyond. Scanned 1e-4
        // apart in φ: the last strip with an unloading has an amplitude
        // below 0.01 (measured 0.0032, the margin −0.0032 there); 0.08 rad
        // before the kink it is 0.099 (the margin −0.099).
        let sc = Scaled::new(
            0.07674175307335356,
            -0.05949359508242826,
            -0.09244197432460992,
            -0.3190521062595738,
            0.0,
        );
        let amp = |phi: f64| {
            let st = sc.strip(f64::sin(phi));
            let (_, t, margin, a) = st.integrate_etd_margin(0.05, 0.1, 0.0);
            (t, margin, a)
        };
        let (t0, m0, a0) = amp(0.44);
        assert_eq!(t0, 2);
        assert!((a0 - m0.abs()).abs() < 0.05 * a0 && a0 > 0.05, "{a0} {m0}");
        let mut last = (0.44, a0);
        let mut phi: f64 = 0.44;
        while phi < 0.53 {
            phi += 1e-4;
            let (t, _, a) = amp(phi);
            if t != 2 {
                assert!(a.is_infinite(), "{phi}: {a}");
                break;
            }
            assert!(a <= last.1 * (1.0 + 1e-9), "{phi}: {a} after {}", last.1);
            last = (phi, a);
        }
        assert!((0.51..0.525).contains(&last.0), "{last:?}");
        println!("at 0.44: {a0} (margin {m0}); last {last:?}");
        assert!(last.1 < 0.01, "{last:?}");
    }

    #[test]
    fn hermite_min_of_a_parabola() {
        // g = (u − 0.3)² − 0.01: g0 = 0.08, g1 = 0.48, g'(0) = −0.6,
        // g'(1) = 1.4; the cubic interpolant is the parabola itself.
        let m = hermite_min(0.08, -0.6, 0.48, 1.4);
        assert!((m + 0.01).abs() < 1e-15, "{m}");
    }
}
