//! The viscous law and the strip it acts on: [`Law`] (the Deborah number D
//! and the reference stress Z0, with the viscous rate ψ, μ = ψ(r)/r and ψ′,
//! capped at [`RATE_MAX`]) and [`VStrip`], one strip's elastic rate and
//! law, made from the elastic/plastic model's strip. The panels
//! across the contact (`mod.rs`) make a `VStrip` for each strip they need
//! and hand it to `strip_sums` (`strip.rs`).

use crate::ep::Strip;

/// Largest viscous rate ψ, μ used (the relaxation is then instantaneous at
/// any step; keeps the 2 × 2 determinants finite).
const RATE_MAX: f64 = 1e100;

/// The viscous law: Deborah number D and reference stress Z0 (`inf`: Maxwell).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Law {
    pub d: f64,
    /// 1/D and 1/Z0.
    id: f64,
    iz0: f64,
    /// ψ(3/2), the largest viscous rate inside the contact.
    pmax: f64,
}

impl Law {
    pub(crate) fn new(z0: f64, d: f64) -> Self {
        let pmax = if z0.is_infinite() {
            1.5 / d
        } else {
            z0 / d * (1.5 / z0).sinh()
        };
        Law {
            d,
            id: 1.0 / d,
            iz0: 1.0 / z0,
            pmax,
        }
    }

    /// (μ, ψ′) at |Z| = r: μ = ψ(r)/r = Z0·sinh(r/Z0)/(D·r) and
    /// ψ′ = cosh(r/Z0)/D (both 1/D at r = 0 and for Z0 = ∞).
    #[inline]
    pub(crate) fn rates(&self, r: f64) -> (f64, f64) {
        let id = self.id;
        let x = r * self.iz0;
        if x < 0.01 {
            // Also Z0 = ∞ (x = 0) and r = 0.
            let x2 = x * x;
            return (
                id * (1.0 + x2 / 6.0 * (1.0 + x2 / 20.0)),
                id * (1.0 + 0.5 * x2 * (1.0 + x2 / 12.0)),
            );
        }
        // 1/(2x·D) beside the exponential, off its chain of dependent
        // operations.
        let hx = 0.5 * id / x;
        let ex = x.min(700.0).exp();
        let ix = 1.0 / ex;
        (
            ((ex - ix) * hx).min(RATE_MAX),
            (0.5 * (ex + ix) * id).min(RATE_MAX),
        )
    }

    /// The largest viscous rate inside the contact, ψ(3/2) (infinite when
    /// it overflows).
    pub(crate) fn psi_max(&self) -> f64 {
        self.pmax
    }

    /// ψ(r) = (Z0/D)·sinh(r/Z0), the viscous strain rate at |Z| = r.
    #[inline]
    pub(crate) fn psi(&self, r: f64) -> f64 {
        (self.rates(r).0 * r).min(RATE_MAX)
    }
}

/// One strip: half-width c, elastic rate e = (a, b1 + q2·X) (= G·v).
#[derive(Debug, Clone, Copy)]
pub(crate) struct VStrip {
    pub c: f64,
    pub a: f64,
    pub b1: f64,
    pub q2: f64,
    pub gy: f64,
    pub law: Law,
    /// The elastic/plastic model's plastic steps for the cap
    /// (`crate::plastic_steps`).
    pub steps: (f64, f64, f64, bool),
}

impl VStrip {
    /// The elastic/plastic model's strip with the viscous law `law`.
    pub(super) fn new(st: Strip, law: Law, steps: (f64, f64, f64, bool)) -> Self {
        VStrip {
            c: st.c,
            a: st.a,
            b1: st.b1,
            q2: st.q2,
            gy: st.gy,
            law,
            steps,
        }
    }

    /// The elastic/plastic strip with this law, whose plastic segments are
    /// the cap ([`Strip::limit_segment`]).
    pub(super) fn limit_strip(&self) -> Strip {
        Strip {
            c: self.c,
            a: self.a,
            b1: self.b1,
            q2: self.q2,
            gy: self.gy,
            vis: Some(self.law),
        }
    }
}
