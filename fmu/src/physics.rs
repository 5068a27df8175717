//! The physics seam: the one place where the FMU asks for contact forces.
//!
//! **Provisional model.** The dimensional contact crate `traction-contact`
//! (issue 5) is not written yet. Until it lands, this module implements the
//! seam with a small, self-contained and tested model; afterwards
//! [`Contact::new`] and [`Contact::evaluate`] only forward to traction-contact
//! and the rest of the FMU does not change.
//!
//! What the provisional model computes:
//!
//! * **Hertz contact** (report section 2-1) of two bodies with principal radii
//!   `rx`, `ry` (a radius of 0 or ±∞ means a flat profile, negative means
//!   concave). With curvature sums `A = ½(1/Rx1 + 1/Rx2)` and
//!   `B = ½(1/Ry1 + 1/Ry2)` and `E* = [(1-ν1²)/E1 + (1-ν2²)/E2]⁻¹`, the semi-axis
//!   ratio `κ = minor/major` solves `B/A = [E(e)/κ² − K(e)] / [K(e) − E(e)]`
//!   (or its inverse), `e² = 1 − κ²`, with the complete elliptic integrals K, E
//!   (arithmetic-geometric mean). Then `minor³ = 3 N E(e) κ / (2π (A+B) E*)`,
//!   `major = minor/κ`, `P0 = 3N / (2π a b)`. The shape depends on the
//!   geometry only, so it is solved once in [`Contact::new`] and each
//!   evaluation scales it with `N^(1/3)`.
//! * **J+T elastic/plastic traction** (Appendix V, eq. 22–24) for slip and
//!   side slip with user values of the initial slope `m` and the peak traction
//!   coefficient `μ` (dimensionless):
//!   `J1 = (3π/8)(m/μ)(ΔU/U)√k`, `J2 = (3π/8)(m/μ)(ΔV/U)√k`,
//!   `S = (2/3)√(J1² + J2²)/√k`,
//!   `ψ = (1/π)[π/2 − asin((1−S²)/(1+S²)) + 2S/(1+S²)]`,
//!   `J4 = (2/3) J1 ψ/(S√k)`, `J5 = (2/3) J2 ψ/(S√k)`, `Fx = μN·J4`,
//!   `Fy = μN·J5`. The rigid/plastic option (eq. 24) uses `ψ = 1`.
//!   `J3 = (3/8)(m/μ)(ω√(ab)/U)√k` (eq. 5) is reported; the spin moment
//!   (`J6`, `Mz`) is **0** in this provisional model, and the FMU logs a warning
//!   the first time it sees spin.
//! * **Zero rolling speed.** The J groups divide by U and grow without bound as
//!   U → 0. The model uses `U_eff = max(|U|, U_reg)` in J1, J2, J3 (U_reg is a
//!   parameter, default 0.01 m/s). Forces are therefore continuous in U through
//!   0, reach the Coulomb-like limit `μN` at large `|ΔU|/U_eff`, follow the
//!   sign of the relative motion (ΔU, ΔV) whatever the rolling direction, and
//!   are exactly zero at zero relative motion (`ψ/S → 4/π` as `S → 0`).
//! * **Contact opening.** A normal load `N ≤ 0` means the bodies separate:
//!   every force, size and J group is 0 and the regime is [`Regime::Open`].
//! * `regime` (Appendix IV fig. 14) is provisional: without spin
//!   [`Regime::ElasticNoSpin`], with spin [`Regime::ElasticWithSpin`] for the
//!   elastic/plastic model, [`Regime::RigidPlastic`] for the rigid/plastic one.
//!
//! Not yet available (errors naming the option, raised when the FMU leaves
//! initialization): the fluid correlations of Santotrac 50 and TDF-88, the
//! viscoelastic rheology, the compliance correction and the spin moment.

use std::f64::consts::PI;

/// The fluid whose slope `m` and peak `μ` the contact uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fluid {
    /// Santotrac 50, through the report's correlations (Appendix III-A).
    Santotrac50,
    /// TDF-88, through the report's correlations (Appendix III-B).
    Tdf88,
    /// The user's `m` and `μ` (parameters `m_user`, `mu_user`).
    User,
}

/// The rheological model of the film.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rheology {
    /// Johnson & Tevaarwerk elastic/plastic (default).
    ElasticPlastic,
    /// Rigid/plastic (eq. 24 of Appendix V).
    RigidPlastic,
    /// Viscoelastic (not in the provisional model).
    Viscoelastic,
}

/// The regime of Appendix IV figure 14, plus an open contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// N ≤ 0: the bodies do not touch.
    Open = 0,
    /// Region I: elastic/plastic analysis without spin suffices.
    ElasticNoSpin = 1,
    /// Region II: elastic/plastic analysis with spin is required.
    ElasticWithSpin = 2,
    /// Region III: rigid/plastic analysis with spin suffices.
    RigidPlastic = 3,
}

/// Geometry, materials, fluid and options of the contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// Body 1 radius of curvature in the rolling (x) direction, m (0 or ±∞: flat).
    pub rx1: f64,
    /// Body 1 radius of curvature across (y), m (0 or ±∞: flat).
    pub ry1: f64,
    /// Body 2 radius of curvature in the rolling (x) direction, m.
    pub rx2: f64,
    /// Body 2 radius of curvature across (y), m.
    pub ry2: f64,
    /// Young's modulus of body 1, Pa.
    pub e1: f64,
    /// Poisson's ratio of body 1 (dimensionless).
    pub nu1: f64,
    /// Young's modulus of body 2, Pa.
    pub e2: f64,
    /// Poisson's ratio of body 2 (dimensionless).
    pub nu2: f64,
    /// Fluid.
    pub fluid: Fluid,
    /// Initial traction slope m (dimensionless), used when `fluid` is `User`.
    pub m_user: f64,
    /// Peak traction coefficient μ (dimensionless), used when `fluid` is `User`.
    pub mu_user: f64,
    /// Rheological model.
    pub rheology: Rheology,
    /// Disc-compliance correction of the slope (Appendix IV A, B).
    pub compliance: bool,
    /// Rolling-speed regularisation U_reg, m/s (> 0).
    pub u_reg: f64,
}

/// One operating state of the contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Inputs {
    /// Normal load N, N (≤ 0: contact open).
    pub load: f64,
    /// Rolling speed U = (u1 + u2)/2, m/s.
    pub u: f64,
    /// Slip ΔU = u1 − u2, m/s.
    pub du: f64,
    /// Side slip ΔV, m/s.
    pub dv: f64,
    /// Spin ω about the contact normal, rad/s.
    pub omega: f64,
    /// Inlet temperature, °C.
    pub inlet_temperature_celsius: f64,
}

/// What the contact gives back (SI units; J groups dimensionless).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// Traction force along x on body 2 (from body 1), N.
    pub fx: f64,
    /// Traction force along y on body 2 (from body 1), N.
    pub fy: f64,
    /// Spin moment about the contact normal on body 2, N·m.
    pub mz: f64,
    /// Semi-axis along x, m.
    pub a: f64,
    /// Semi-axis across, m.
    pub b: f64,
    /// Aspect ratio k = b/a (dimensionless; 0 when open).
    pub k: f64,
    /// Maximum Hertz pressure P0, Pa.
    pub p0: f64,
    /// Slope m used (dimensionless).
    pub m: f64,
    /// Peak traction coefficient μ used (dimensionless).
    pub mu: f64,
    /// J1..J7 (dimensionless), `j[0]` is J1.
    pub j: [f64; 7],
    /// Regime.
    pub regime: Option<Regime>,
}

/// Why the contact cannot be built or evaluated. Each message names the
/// quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PhysicsError {
    /// A parameter or input is outside its valid range.
    #[error("{name} = {value} is invalid: {valid}")]
    Invalid {
        /// The quantity.
        name: &'static str,
        /// The offending value.
        value: f64,
        /// The valid range.
        valid: &'static str,
    },
    /// The option is not available in the provisional model.
    #[error(
        "{0} is not available in the provisional contact model of the FMU (it arrives with traction-contact, issue 5)"
    )]
    NotYetAvailable(&'static str),
}

fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    valid: &'static str,
) -> Result<(), PhysicsError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(PhysicsError::Invalid { name, value, valid })
    }
}

/// Curvature 1/R of a principal radius; 0 and ±∞ mean flat.
fn curvature(name: &'static str, r: f64) -> Result<f64, PhysicsError> {
    if r.is_nan() {
        return Err(PhysicsError::Invalid {
            name,
            value: r,
            valid: "a radius in m (0 or ±inf for flat, negative for concave)",
        });
    }
    Ok(if r == 0.0 || r.is_infinite() {
        0.0
    } else {
        1.0 / r
    })
}

/// Complete elliptic integrals K(m) and E(m) of parameter m = e² ∈ [0, 1),
/// by the arithmetic-geometric mean.
pub fn elliptic_ke(m: f64) -> (f64, f64) {
    let mut a = 1.0_f64;
    let mut b = (1.0 - m).sqrt();
    let mut c2 = m; // c_0² = m
    let mut sum = 0.5 * c2; // Σ 2^(n-1) c_n², n = 0
    let mut pow = 0.5;
    for _ in 0..40 {
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
        let an = 0.5 * (a + b);
        let bn = (a * b).sqrt();
        let cn = 0.5 * (a - b);
        pow *= 2.0;
        c2 = cn * cn;
        sum += pow * c2;
        a = an;
        b = bn;
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// Curvature ratio `large/small` produced by a semi-axis ratio κ = minor/major.
fn curvature_ratio(kappa: f64) -> f64 {
    let m = 1.0 - kappa * kappa;
    let (k, e) = elliptic_ke(m);
    (e / (kappa * kappa) - k) / (k - e)
}

/// The contact, built once from its parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    params: Parameters,
    /// `minor = minor_coef · N^(1/3)`.
    minor_coef: f64,
    /// κ = minor/major.
    kappa: f64,
    /// The minor axis lies along x (so k = b/a = 1/κ ≥ 1).
    minor_along_x: bool,
    m: f64,
    mu: f64,
}

impl Contact {
    /// Validates the parameters and solves the geometry-only part of Hertz.
    ///
    /// # Errors
    /// A [`PhysicsError`] naming the first invalid parameter or unavailable option.
    pub fn new(p: &Parameters) -> Result<Self, PhysicsError> {
        let c = [
            curvature("rx1", p.rx1)?,
            curvature("ry1", p.ry1)?,
            curvature("rx2", p.rx2)?,
            curvature("ry2", p.ry2)?,
        ];
        let ca = 0.5 * (c[0] + c[2]);
        let cb = 0.5 * (c[1] + c[3]);
        check(
            "curvature sum along x, 1/rx1 + 1/rx2",
            2.0 * ca,
            ca > 0.0,
            "> 0 (the bodies must conform less than they curve)",
        )?;
        check(
            "curvature sum across, 1/ry1 + 1/ry2",
            2.0 * cb,
            cb > 0.0,
            "> 0 (the bodies must conform less than they curve)",
        )?;
        check("e1", p.e1, p.e1 > 0.0, "Young's modulus in Pa, > 0")?;
        check("e2", p.e2, p.e2 > 0.0, "Young's modulus in Pa, > 0")?;
        check(
            "nu1",
            p.nu1,
            p.nu1 > -1.0 && p.nu1 < 0.5,
            "Poisson's ratio in (-1, 0.5)",
        )?;
        check(
            "nu2",
            p.nu2,
            p.nu2 > -1.0 && p.nu2 < 0.5,
            "Poisson's ratio in (-1, 0.5)",
        )?;
        check(
            "rolling_speed_regularisation",
            p.u_reg,
            p.u_reg > 0.0,
            "> 0 m/s",
        )?;
        match p.fluid {
            Fluid::User => {}
            Fluid::Santotrac50 => {
                return Err(PhysicsError::NotYetAvailable(
                    "fluid = santotrac_50 (fluid correlations)",
                ));
            }
            Fluid::Tdf88 => {
                return Err(PhysicsError::NotYetAvailable(
                    "fluid = tdf_88 (fluid correlations)",
                ));
            }
        }
        check(
            "m_user",
            p.m_user,
            p.m_user > 0.0,
            "initial traction slope, > 0",
        )?;
        check(
            "mu_user",
            p.mu_user,
            p.mu_user > 0.0 && p.mu_user < 1.0,
            "peak traction coefficient in (0, 1)",
        )?;
        if p.rheology == Rheology::Viscoelastic {
            return Err(PhysicsError::NotYetAvailable(
                "rheology_model = viscoelastic",
            ));
        }
        if p.compliance {
            return Err(PhysicsError::NotYetAvailable(
                "compliance_correction = true",
            ));
        }
        let e_star = 1.0 / ((1.0 - p.nu1 * p.nu1) / p.e1 + (1.0 - p.nu2 * p.nu2) / p.e2);
        let (small, large) = if ca >= cb { (cb, ca) } else { (ca, cb) };
        let ratio = large / small;
        // The axis with the larger curvature carries the minor semi-axis.
        let kappa = if ratio - 1.0 <= 1e-12 {
            1.0
        } else {
            // curvature_ratio falls monotonically from +∞ (κ → 0) to 1 (κ = 1).
            let (mut lo, mut hi) = (1e-9_f64, 1.0_f64);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if curvature_ratio(mid) > ratio {
                    lo = mid;
                } else {
                    hi = mid;
                }
                if hi - lo <= 1e-15 {
                    break;
                }
            }
            0.5 * (lo + hi)
        };
        let (_, e_int) = elliptic_ke(1.0 - kappa * kappa);
        let minor_coef = (3.0 * e_int * kappa / (2.0 * PI * (ca + cb) * e_star)).cbrt();
        let (m, mu) = (p.m_user, p.mu_user);
        Ok(Self {
            params: *p,
            minor_coef,
            kappa,
            minor_along_x: ca >= cb,
            m,
            mu,
        })
    }

    /// The parameters the contact was built from.
    pub fn parameters(&self) -> &Parameters {
        &self.params
    }

    /// Evaluates the contact at one operating state.
    ///
    /// # Errors
    /// [`PhysicsError::Invalid`] when an input is NaN or infinite, or the
    /// inlet temperature is below absolute zero.
    pub fn evaluate(&self, i: &Inputs) -> Result<Outputs, PhysicsError> {
        let any = "a finite value";
        check(
            "normal_load",
            i.load,
            true,
            "a finite force in N (<= 0 opens the contact)",
        )?;
        check("rolling speed U", i.u, true, any)?;
        check("slip velocity dU", i.du, true, any)?;
        check("side slip velocity dV", i.dv, true, any)?;
        check("spin", i.omega, true, any)?;
        check(
            "inlet_temperature",
            i.inlet_temperature_celsius,
            i.inlet_temperature_celsius > -273.15,
            "a temperature in degC above -273.15",
        )?;
        let (m, mu) = (self.m, self.mu);
        if i.load <= 0.0 {
            return Ok(Outputs {
                m,
                mu,
                regime: Some(Regime::Open),
                ..Outputs::default()
            });
        }
        let minor = self.minor_coef * i.load.cbrt();
        let major = minor / self.kappa;
        let (a, b) = if self.minor_along_x {
            (minor, major)
        } else {
            (major, minor)
        };
        let k = b / a;
        let p0 = 3.0 * i.load / (2.0 * PI * a * b);
        let u_eff = i.u.abs().max(self.params.u_reg);
        let sk = k.sqrt();
        let g = 3.0 * PI / 8.0 * (m / mu) * sk / u_eff;
        let j1 = g * i.du;
        let j2 = g * i.dv;
        let j3 = 3.0 / 8.0 * (m / mu) * (i.omega * (a * b).sqrt() / u_eff) * sk;
        let rho = j1.hypot(j2);
        let s = 2.0 / 3.0 * rho / sk;
        let rigid = self.params.rheology == Rheology::RigidPlastic;
        // J4 = (2/3) J1 ψ/(S√k) = ψ · J1/√(J1²+J2²): no 0/0 except at
        // J1 = J2 = 0, where the traction is 0. ψ is evaluated through the
        // identity π/2 − asin((1−S²)/(1+S²)) = 2 atan S (S ≥ 0), which equals
        // the report's form but has no cancellation as S → 0.
        let (j4, j5) = if rho == 0.0 {
            (0.0, 0.0)
        } else {
            let psi = if rigid {
                1.0
            } else {
                (2.0 * s.atan() + 2.0 * s / (1.0 + s * s)) / PI
            };
            (psi * (j1 / rho), psi * (j2 / rho))
        };
        let (j6, mz) = (0.0, 0.0);
        let j7 = j1 * j4 + j2 * j5 + j3 * j6;
        let regime = if rigid {
            Regime::RigidPlastic
        } else if i.omega == 0.0 {
            Regime::ElasticNoSpin
        } else {
            Regime::ElasticWithSpin
        };
        Ok(Outputs {
            fx: mu * i.load * j4,
            fy: mu * i.load * j5,
            mz,
            a,
            b,
            k,
            p0,
            m,
            mu,
            j: [j1, j2, j3, j4, j5, j6, j7],
            regime: Some(regime),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel_twin_disc() -> Parameters {
        // High speed machine, k = 1 discs of Table 2-1 (upper Rx 33, Ry 22.6;
        // lower Rx 71.4, Ry flat), steel.
        Parameters {
            rx1: 0.033,
            ry1: 0.0226,
            rx2: 0.0714,
            ry2: 0.0,
            e1: 2.07e11,
            nu1: 0.3,
            e2: 2.07e11,
            nu2: 0.3,
            fluid: Fluid::User,
            m_user: 35.0,
            mu_user: 0.075,
            rheology: Rheology::ElasticPlastic,
            compliance: false,
            u_reg: 0.01,
        }
    }

    fn sphere_on_flat(r: f64) -> Parameters {
        Parameters {
            rx1: r,
            ry1: r,
            rx2: 0.0,
            ry2: f64::INFINITY,
            ..steel_twin_disc()
        }
    }

    fn op(load: f64, u: f64, du: f64, dv: f64) -> Inputs {
        Inputs {
            load,
            u,
            du,
            dv,
            omega: 0.0,
            inlet_temperature_celsius: 40.0,
        }
    }

    #[test]
    fn elliptic_integrals_match_tabulated_values() {
        // Abramowitz & Stegun table 17.1: K(0.5) = 1.854074677, E(0.5) = 1.350643881.
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677_301_372).abs() < 1e-12);
        assert!((e - 1.350_643_881_047_675).abs() < 1e-12);
        let (k0, e0) = elliptic_ke(0.0);
        assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
    }

    #[test]
    fn circular_hertz_matches_closed_form() {
        // Sphere R = 10 mm on a flat, N = 100 N: a³ = 3NR/(4E*), P0 = 3N/(2πa²).
        let p = sphere_on_flat(0.01);
        let c = Contact::new(&p).unwrap();
        let o = c.evaluate(&op(100.0, 1.0, 0.0, 0.0)).unwrap();
        let e_star: f64 = 2.07e11 / (2.0 * (1.0 - 0.09));
        let a = (3.0 * 100.0 * 0.01 / (4.0 * e_star)).cbrt();
        assert!((o.a - a).abs() < 1e-12 * a.max(1.0), "{} vs {a}", o.a);
        assert!((o.b - a).abs() < 1e-12);
        assert!((o.k - 1.0).abs() < 1e-12);
        assert!((o.p0 - 3.0 * 100.0 / (2.0 * PI * a * a)).abs() < 1e-6 * o.p0);
    }

    #[test]
    fn table_2_2_contact_size_factor() {
        // Report Table 2-2: a/P0 = C = 0.307e-12 m/Pa for the k = 1 discs of
        // the high speed machine. The report's E' for steel is not printed
        // exactly; 2 % covers E = 200..210 GPa.
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let o = c.evaluate(&op(500.0, 10.0, 0.0, 0.0)).unwrap();
        let ratio = o.a / o.p0;
        assert!((ratio / 0.307e-12 - 1.0).abs() < 0.02, "C = {ratio:e}");
        assert!((o.k - 1.0).abs() < 0.01, "k = {}", o.k);
    }

    #[test]
    fn elliptical_hertz_obeys_load_balance_and_curvature_relation() {
        // k = 5 discs (upper Rx 33, Ry 270; lower Rx 71.4, flat): the minor axis is
        // along x. Check the two Hertz relations independently of the solver's
        // formulas: N = (2/3)π a b P0, and the curvature ratio equation.
        let p = Parameters {
            ry1: 0.270,
            ..steel_twin_disc()
        };
        let c = Contact::new(&p).unwrap();
        let o = c.evaluate(&op(800.0, 10.0, 0.0, 0.0)).unwrap();
        assert!(o.k > 1.0);
        assert!((2.0 / 3.0 * PI * o.a * o.b * o.p0 / 800.0 - 1.0).abs() < 1e-12);
        let (ca, cb) = (0.5 * (1.0 / 0.033 + 1.0 / 0.0714), 0.5 / 0.270);
        assert!((curvature_ratio(o.a / o.b) / (ca / cb) - 1.0).abs() < 1e-9);
        // Report Table 2-1/2-2 quote k = 5 for these discs.
        assert!((o.k - 5.0).abs() < 0.5, "k = {}", o.k);
        // Swapping x and y swaps a and b.
        let q = Parameters {
            rx1: 0.270,
            ry1: 0.033,
            rx2: 0.0,
            ry2: 0.0714,
            ..p
        };
        let o2 = Contact::new(&q)
            .unwrap()
            .evaluate(&op(800.0, 10.0, 0.0, 0.0))
            .unwrap();
        assert!((o2.a - o.b).abs() < 1e-15 && (o2.b - o.a).abs() < 1e-15);
    }

    /// ψ written as printed in Appendix V (eq. 22, 23).
    fn psi_hand(s: f64) -> f64 {
        (PI / 2.0 - ((1.0 - s * s) / (1.0 + s * s)).asin() + 2.0 * s / (s * s + 1.0)) / PI
    }

    #[test]
    fn traction_matches_hand_calculation() {
        let p = steel_twin_disc();
        let c = Contact::new(&p).unwrap();
        for &(du, dv) in &[
            (0.05, 0.0),
            (0.2, 0.1),
            (-0.02, 0.3),
            (1.0, -1.0),
            (0.0001, 0.0),
        ] {
            let (load, u) = (600.0, 20.0);
            let o = c.evaluate(&op(load, u, du, dv)).unwrap();
            let g = 3.0 * PI / 8.0 * (35.0 / 0.075) * o.k.sqrt();
            let (j1, j2) = (g * du / u, g * dv / u);
            let s = 2.0 / 3.0 * (j1 * j1 + j2 * j2).sqrt() / o.k.sqrt();
            let psi = psi_hand(s);
            let fx = 0.075 * load * psi * j1 / (j1 * j1 + j2 * j2).sqrt();
            let fy = 0.075 * load * psi * j2 / (j1 * j1 + j2 * j2).sqrt();
            assert!((o.fx - fx).abs() <= 1e-9 * load, "fx {} vs {fx}", o.fx);
            assert!((o.fy - fy).abs() <= 1e-9 * load, "fy {} vs {fy}", o.fy);
            assert!((o.j[0] - j1).abs() <= 1e-9 * j1.abs().max(1.0));
            assert!(o.j[6] >= 0.0);
        }
    }

    #[test]
    fn initial_slope_is_m_and_large_slip_gives_mu() {
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let (load, u) = (600.0, 20.0);
        // Small slip: Fx/N = m ΔU/U.
        let du = 1e-6 * u;
        let o = c.evaluate(&op(load, u, du, 0.0)).unwrap();
        assert!((o.fx / load / (35.0 * du / u) - 1.0).abs() < 1e-6);
        // Large slip: Fx → μN.
        let o = c.evaluate(&op(load, u, 10.0 * u, 0.0)).unwrap();
        assert!((o.fx / (0.075 * load) - 1.0).abs() < 1e-4);
    }

    #[test]
    fn zero_rolling_speed_is_continuous_and_zero_relative_motion_gives_zero_force() {
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let f = |u: f64, du: f64| c.evaluate(&op(600.0, u, du, 0.0)).unwrap().fx;
        assert_eq!(f(0.0, 0.0), 0.0);
        assert_eq!(f(20.0, 0.0), 0.0);
        // Continuity through U = 0 at fixed slip, and symmetry in U.
        for &du in &[1e-4, 1e-3, 0.1] {
            let (l, z, r) = (f(-1e-9, du), f(0.0, du), f(1e-9, du));
            assert!((l - z).abs() < 1e-9 && (r - z).abs() < 1e-9);
            assert_eq!(f(-3.0, du), f(3.0, du));
            // Force follows the slip direction.
            assert!(f(0.0, du) > 0.0 && f(0.0, -du) < 0.0);
            assert_eq!(f(0.0, -du), -f(0.0, du));
        }
        // Hand value at U = 0: U_eff = U_reg.
        let o = c.evaluate(&op(600.0, 0.0, 0.001, 0.0)).unwrap();
        let g = 3.0 * PI / 8.0 * (35.0 / 0.075) * o.k.sqrt();
        let s = 2.0 / 3.0 * g * 0.001 / 0.01 / o.k.sqrt();
        assert!((o.fx - 0.075 * 600.0 * psi_hand(s)).abs() < 1e-9);
    }

    #[test]
    fn small_slip_limit_has_no_cancellation() {
        // As S → 0, J4 → (8/(3π)) J1/√k, i.e. Fx → m N ΔU/U (slope m) exactly;
        // the printed asin form loses digits there, the atan form must not.
        let c = Contact::new(&steel_twin_disc()).unwrap();
        for &du in &[1e-14, 1e-10, 1e-6] {
            let o = c.evaluate(&op(600.0, 20.0, du, 0.0)).unwrap();
            let linear = 35.0 * 600.0 * du / 20.0;
            assert!(
                (o.fx / linear - 1.0).abs() < 1e-9,
                "du {du}: {} vs {linear}",
                o.fx
            );
        }
    }

    #[test]
    fn open_contact_gives_zeros_and_errors_name_the_quantity() {
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let o = c.evaluate(&op(-5.0, 20.0, 1.0, 1.0)).unwrap();
        assert_eq!((o.fx, o.fy, o.a, o.p0), (0.0, 0.0, 0.0, 0.0));
        assert_eq!(o.regime, Some(Regime::Open));
        let e = c.evaluate(&op(f64::NAN, 20.0, 1.0, 1.0)).unwrap_err();
        assert!(e.to_string().contains("normal_load"), "{e}");
        let bad = Parameters {
            mu_user: 1.5,
            ..steel_twin_disc()
        };
        assert!(
            Contact::new(&bad)
                .unwrap_err()
                .to_string()
                .contains("mu_user")
        );
        let conform = Parameters {
            rx2: -0.033,
            ..steel_twin_disc()
        };
        assert!(
            Contact::new(&conform)
                .unwrap_err()
                .to_string()
                .contains("curvature sum along x")
        );
        let fluid = Parameters {
            fluid: Fluid::Tdf88,
            ..steel_twin_disc()
        };
        assert!(matches!(
            Contact::new(&fluid),
            Err(PhysicsError::NotYetAvailable(_))
        ));
    }

    #[test]
    fn rigid_plastic_is_coulomb_in_the_slip_direction() {
        let p = Parameters {
            rheology: Rheology::RigidPlastic,
            ..steel_twin_disc()
        };
        let o = Contact::new(&p)
            .unwrap()
            .evaluate(&op(600.0, 20.0, 0.3, 0.4))
            .unwrap();
        assert!((o.fx - 0.075 * 600.0 * 0.6).abs() < 1e-9);
        assert!((o.fy - 0.075 * 600.0 * 0.8).abs() < 1e-9);
    }
}
