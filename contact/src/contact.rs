//! The traction contact: Hertz, fluid, compliance, J groups, rheology,
//! frames, regime and the thermal fixed point.

use std::f64::consts::PI;

use traction_hertz::{Body, Geometry};
use traction_rheology::Inputs;
use traction_rheology::map::Budget;

use crate::error::ContactError;
use crate::fluid::correlate;
use crate::map_cache::MapCache;
use crate::thermal::{self, Film};
use crate::{
    Accuracy, Compliance, Direction, Evaluation, Fluid, Map, MapStats, Model, OperatingState,
    Options, OutsideEnvelope, Properties, ROLLING_SPEED_FLOOR_RANGE, Regime,
};

/// The traction contact, built once from the bodies, the fluid and the options.
#[derive(Debug, Clone)]
pub struct TractionContact {
    geometry: Geometry,
    fluid: Fluid,
    options: Options,
    /// Kalker q_x, q_y and the disc shear modulus, when compliance is on.
    discs: Option<(f64, f64, f64)>,
    /// The interpolation map of [`Options::map`] (empty until first used).
    map: MapCache,
}

/// Two contacts are equal when their definitions are (geometry, fluid,
/// options, disc compliance); the interpolation map is a cache of values that
/// depend only on those, so it takes no part.
impl PartialEq for TractionContact {
    fn eq(&self, other: &Self) -> bool {
        self.geometry == other.geometry
            && self.fluid == other.fluid
            && self.options == other.options
            && self.discs == other.discs
    }
}

/// The fluid's m, μ, μ_f at the inlet temperature, before the compliance
/// correction, and whether m is the film's own slope (physical fluid).
#[derive(Debug, Clone, Copy)]
struct Inlet {
    m: f64,
    mu: f64,
    mu_f: f64,
    film: Option<f64>,
}

/// A solved state at given properties.
#[derive(Debug, Clone, Copy)]
struct Solved {
    f: [f64; 3],
    loss: f64,
    j: [f64; 7],
    /// The dominant rolling frame's solution (for the regime).
    dominant: Option<Branch>,
}

/// The rheology's outputs are finite for finite inputs (its contract, tested
/// over the whole input range); should a solver failure ever break that, the
/// caller gets [`ContactError::NonFinite`] naming the first such output, not
/// NaN forces (a NaN loss would also read as 0 after `max(0.0)`).
pub(crate) fn finite_outputs(values: &[(&'static str, f64)]) -> Result<(), ContactError> {
    match values.iter().find(|(_, v)| !v.is_finite()) {
        Some(&(quantity, value)) => Err(ContactError::NonFinite { quantity, value }),
        None => Ok(()),
    }
}

/// The dimensionless solution of one rolling frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Branch {
    pub(crate) j: [f64; 3],
    pub(crate) out: [f64; 3],
}

impl TractionContact {
    /// Build the contact: Hertz geometry of the two bodies (errors name bad
    /// radii, materials, conformal contact), k within the rheology's range
    /// [0.01, 100], Kalker's q_x, q_y if compliance is on.
    pub fn new(
        body1: &Body,
        body2: &Body,
        fluid: Fluid,
        options: Options,
    ) -> Result<Self, ContactError> {
        fluid.validate()?;
        ROLLING_SPEED_FLOOR_RANGE.check("rolling-speed floor U_f", options.rolling_speed_floor)?;
        if let Some(th) = options.thermal {
            th.validate()?;
            let spin_peak = match &fluid {
                Fluid::Constant { spin_peak, .. } => spin_peak.is_some(),
                Fluid::Report { spin_peak, .. } => *spin_peak,
                Fluid::Physical { .. } => false,
            };
            if spin_peak {
                return Err(ContactError::OutOfRange {
                    quantity: "spin-peak traction coefficient μ_s with the thermal model",
                    value: f64::NAN,
                    valid: "not both: the spin-peak μ_s is the report's empirical correction for the heating the thermal model computes",
                });
            }
            let user = !matches!(fluid, Fluid::Report { .. });
            if user && th.mu_coefficient.is_none() {
                return Err(ContactError::OutOfRange {
                    quantity: "temperature coefficient β_μ of μ (1/K)",
                    value: f64::NAN,
                    valid: "required for a user fluid (Thermal::mu_coefficient, in [−1, 1] 1/K)",
                });
            }
            if user && th.fluid_conductivity.is_none() {
                return Err(ContactError::OutOfRange {
                    quantity: "fluid thermal conductivity k_f (W/(m·K))",
                    value: f64::NAN,
                    valid: "required for a user fluid (Thermal::fluid_conductivity, in (0, 1e4] W/(m·K))",
                });
            }
            if matches!(fluid, Fluid::Constant { .. }) && th.film == Film::FromFluid {
                return Err(ContactError::OutOfRange {
                    quantity: "film thickness h (m)",
                    value: f64::NAN,
                    valid: "required for user m, μ: Film::Thickness or Film::HamrockDowson",
                });
            }
            if user && th.film == Film::FromFluidInletHeated {
                return Err(ContactError::OutOfRange {
                    quantity: "film thickness h (m)",
                    value: f64::NAN,
                    valid: "Film::FromFluidInletHeated needs a report fluid's η₀(θ); for a user fluid: Film::HamrockDowsonInletHeated",
                });
            }
        }
        let geometry = Geometry::new(body1, body2)?;
        let k = geometry.k;
        // The traction model's range, checked here to name the contact's k.
        traction_rheology::ASPECT_RATIO_RANGE.check("aspect ratio k = b/a of the contact", k)?;
        let discs = match options.compliance {
            Compliance::Off => None,
            Compliance::Discs { material, .. } => {
                let gs = material.shear_modulus()?;
                let nu = material.poisson_ratio;
                let qx = traction_compliance::kalker_q(Direction::Longitudinal, k, nu)?;
                let qy = traction_compliance::kalker_q(Direction::Side, k, nu)?;
                Some((qx, qy, gs))
            }
        };
        Ok(TractionContact {
            geometry,
            fluid,
            options,
            discs,
            map: MapCache::default(),
        })
    }

    /// Move the interpolation map out of this contact (None if it has none),
    /// e.g. to hand it to a contact rebuilt with other loads or fluids.
    pub fn take_map(&self) -> Option<Map> {
        self.map.lock().take()
    }

    /// Adopt a map built by another contact. Its values depend only on k and
    /// the accuracy, so it is kept when those match this contact's and
    /// [`Options::map`] is on (returns true); otherwise it is dropped.
    pub fn adopt_map(&self, map: Map) -> bool {
        let ok = self.options.map
            && map.key() == (self.geometry.k, 0.0, 1.0)
            && map.tol() == self.options.accuracy.tol();
        if ok {
            // The contact's maps spend within its budget (a map built
            // elsewhere without it gets it, with the initial credit).
            let map = if map.budget() == Some(Budget::DEFAULT) {
                map
            } else {
                map.with_budget(Budget::DEFAULT)
            };
            *self.map.lock() = Some(map);
        }
        ok
    }

    /// Counters of the interpolation map ([`Options::map`]); None until the
    /// map is first used.
    pub fn map_stats(&self) -> Option<MapStats> {
        self.map.lock().as_ref().map(Map::stats)
    }

    /// The precomputed Hertz geometry.
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The fluid.
    pub fn fluid(&self) -> &Fluid {
        &self.fluid
    }

    /// The options.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The fluid's m, μ and μ_f at the inlet temperature (before the
    /// compliance correction), and the envelope flags.
    fn inlet(
        &self,
        a: f64,
        b: f64,
        p0: f64,
        load: f64,
        state: &OperatingState,
    ) -> Result<(Inlet, OutsideEnvelope), ContactError> {
        let mut flags = OutsideEnvelope::default();
        let (m, mu, mu_f, film) = match &self.fluid {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => (*slope, *peak, spin_peak.unwrap_or(*peak), None),
            Fluid::Physical {
                shear_modulus,
                limiting_stress,
                film_thickness,
            } => {
                let mu = limiting_stress * PI * a * b / load;
                let m = 8.0 / 3.0 * shear_modulus * a * a * b / (load * film_thickness);
                (m, mu, mu, Some(*film_thickness))
            }
            Fluid::Report {
                fluid,
                envelope,
                spin_peak,
                at_inlet,
            } => {
                let speed = state.rolling_speed.abs();
                let z =
                    state.spin.abs() * (a * b).sqrt() / speed.max(self.options.rolling_speed_floor);
                let base = traction_fluids::Query {
                    p0_pa: p0,
                    speed_m_s: speed,
                    theta_celsius: state.inlet_temperature_celsius,
                    k: self.geometry.k,
                    z: 0.0,
                };
                let (m, mu) = match at_inlet {
                    Some(v) => (v.slope, v.peak),
                    None => (
                        correlate(&fluid.slope, base, *envelope, &mut flags)?,
                        correlate(&fluid.mu, base, *envelope, &mut flags)?,
                    ),
                };
                let mu_f = if *spin_peak {
                    correlate(
                        &fluid.spin_mu,
                        traction_fluids::Query { z, ..base },
                        *envelope,
                        &mut flags,
                    )?
                } else {
                    mu
                };
                (m, mu, mu_f, None)
            }
        };
        Ok((Inlet { m, mu, mu_f, film }, flags))
    }

    /// Slopes (m_x, m_y) from the fluid's slope m (disc compliance, if on).
    fn slopes(&self, m: f64, p0: f64, physical: bool) -> Result<(f64, f64), ContactError> {
        Ok(match (self.discs, self.options.compliance) {
            (
                Some((qx, qy, gs)),
                Compliance::Discs {
                    slope_measured_in, ..
                },
            ) => {
                if physical {
                    // Film and discs in series (A3 with B3): 1/m = 1/m_film + 1/m'.
                    let dry = |q: f64| 1.5 * gs / (q * p0);
                    (
                        1.0 / (1.0 / m + 1.0 / dry(qx)),
                        1.0 / (1.0 / m + 1.0 / dry(qy)),
                    )
                } else {
                    let c = |slope, q| traction_compliance::SlopeContact {
                        slope,
                        q,
                        a: 1.0,
                        h: 1.0,
                    };
                    match slope_measured_in {
                        Direction::Longitudinal => {
                            let my =
                                traction_compliance::convert_slope(c(m, qx), c(0.0, qy), p0, gs)?;
                            (m, my)
                        }
                        Direction::Side => {
                            let mx =
                                traction_compliance::convert_slope(c(m, qy), c(0.0, qx), p0, gs)?;
                            (mx, m)
                        }
                    }
                }
            }
            _ => (m, m),
        })
    }

    /// Whether [`Options::map`] is on and applies (elastic/plastic model,
    /// default properties, accuracy within the map's range); the
    /// elastic/plastic map needs gy = 1 in addition, the rigid/plastic one
    /// (regime classification) does not depend on gy.
    pub(crate) fn map_applies(&self) -> bool {
        self.options.map
            && self.options.model == Model::ElasticPlastic
            && self.options.properties == Properties::default()
            && traction_rheology::map::TOLERANCE_RANGE.contains(self.options.accuracy.tol())
    }

    /// Run `f` on the contact's map (built empty on first use).
    pub(crate) fn with_map<T>(
        &self,
        f: impl FnOnce(&mut Map) -> Result<T, traction_rheology::RheologyError>,
    ) -> Result<T, ContactError> {
        let mut slot = self.map.lock();
        let map = match slot.as_mut() {
            Some(map) => map,
            None => slot.insert(
                Map::new(self.geometry.k, 0.0, 1.0, self.options.accuracy)?
                    .with_budget(Budget::DEFAULT),
            ),
        };
        Ok(f(map)?)
    }

    /// Solve the rheology in one rolling frame.
    fn branch(
        &self,
        k: f64,
        j: [f64; 3],
        gy: f64,
        accuracy: Accuracy,
    ) -> Result<Branch, ContactError> {
        if j == [0.0; 3] {
            return Ok(Branch { j, out: [0.0; 3] });
        }
        let inp = Inputs::new(k, j[0], j[1], j[2])?.with_stiffness_ratio(gy)?;
        if self.map_applies() && gy == 1.0 {
            // Without spin the map answers with the elastic/plastic closed
            // form (its `evaluate`); called here directly, the same numbers
            // cost neither the map's lock nor its key check (5 % of the
            // FMU's step without spin). Not counted in the map's
            // `closed_form` statistic.
            let o = if j[2] == 0.0 {
                traction_rheology::evaluate(&inp, Model::ElasticPlastic, self.options.accuracy)?
            } else {
                self.with_map(|m| m.evaluate(&inp))?
            };
            return Ok(Branch {
                j,
                out: [o.j4, o.j5, o.j6],
            });
        }
        let o = match self.options.model {
            Model::ElasticPlastic => traction_rheology::evaluate(
                &inp,
                Model::PropertyVariation(self.options.properties),
                accuracy,
            )?,
            model => traction_rheology::evaluate(&inp, model, accuracy)?,
        };
        Ok(Branch {
            j,
            out: [o.j4, o.j5, o.j6],
        })
    }

    /// Evaluate the contact at an operating state.
    ///
    /// Errors name the quantity: a state out of range, a fluid that gives an
    /// invalid slope, a failed compliance conversion, a thermal fixed point
    /// that does not converge. Every returned number is finite.
    pub fn evaluate(&self, state: &OperatingState) -> Result<Evaluation, ContactError> {
        state.validate()?;
        if state.load == 0.0 {
            return Ok(self.open(state));
        }
        let hz = self.geometry.at_load(state.load)?;
        let (a, b, p0, n) = (hz.a, hz.b, hz.p0, state.load);
        let (inlet, outside_envelope) = self.inlet(a, b, p0, n, state)?;
        let physical = inlet.film.is_some();
        let physical_film = inlet.film;
        let at_accuracy = |m: f64, mu: f64, mu_f: f64, accuracy| {
            let (mx, my) = self.slopes(m, p0, physical)?;
            let s = self.solve(state, [a, b], [mx, my, mu, mu_f], accuracy)?;
            Ok::<_, ContactError>((s, [mx, my, mu, mu_f]))
        };
        let at = |m: f64, mu: f64, mu_f: f64| at_accuracy(m, mu, mu_f, self.options.accuracy);
        let (solved, [mx, my, mu, mu_f], temperature_rise) = match self.options.thermal {
            None => {
                let (s, p) = at(inlet.m, inlet.mu, inlet.mu_f)?;
                (s, p, 0.0)
            }
            Some(th) => {
                let model = thermal::ContactThermal::new(
                    self,
                    &th,
                    state,
                    &hz,
                    physical_film,
                    (inlet.m, inlet.mu),
                )?;
                // m and μ at the rise dt; a temperature law that leaves the
                // float range there (μ = ∞ at β_μ = −0.5/K near 2000 K) is
                // an error, not NaN forces.
                let props = |dt: f64| {
                    let (fm, fmu) = model.factors(dt);
                    let (m, mu) = (inlet.m * fm, inlet.mu * fmu);
                    if m.is_finite() && m > 0.0 && mu.is_finite() && mu > 0.0 {
                        Ok((m, mu))
                    } else {
                        Err(ContactError::Thermal {
                            reason: "the temperature law of m or μ leaves the float range at this rise",
                            temperature_rise: dt,
                        })
                    }
                };
                // With spin, the first evaluation (far from the root) at a
                // ten times coarser accuracy, the others at the contact's;
                // without spin every one at the contact's (the closed forms
                // cost the same at any accuracy). The solver returns a
                // temperature at which it has just evaluated the contact:
                // that evaluation is kept when it was a full one.
                let coarse = if state.spin != 0.0 {
                    thermal::iteration_accuracy(self.options.accuracy)
                } else {
                    self.options.accuracy
                };
                let mut last = None;
                let mut count = 0;
                let (dt, _) = thermal::solve_fixed_point_with_slope(model.start(), |dt| {
                    let (m, mu) = props(dt)?;
                    count += 1;
                    let acc = if count <= 1 {
                        coarse
                    } else {
                        self.options.accuracy
                    };
                    let (s, p) = at_accuracy(m, mu, mu, acc)?;
                    let rise = model.rise(s.loss);
                    // The solver reads the slope of its first evaluation only.
                    let slope = if count == 1 {
                        model.log_slope(self.geometry.k, &s.j, dt, rise)
                    } else {
                        0.0
                    };
                    last = Some((dt, acc == self.options.accuracy, s, p));
                    Ok((rise, slope))
                })?;
                match last {
                    Some((t, true, s, p)) if t == dt => (s, p, dt),
                    _ => {
                        let (m, mu) = props(dt)?;
                        let (s, p) = at(m, mu, mu)?;
                        (s, p, dt)
                    }
                }
            }
        };
        let regime = match solved.dominant {
            Some(br) if self.options.classify_regime => self.classify(self.geometry.k, &br)?,
            _ if self.options.classify_regime => Regime::ElasticWithoutSpin,
            _ => Regime::NotClassified,
        };
        let [j1, j2, j3, j4, j5, j6, j7] = solved.j;
        Ok(Evaluation {
            fx: solved.f[0],
            fy: solved.f[1],
            mz: solved.f[2],
            traction_x: solved.f[0] / n,
            traction_y: solved.f[1] / n,
            loss: solved.loss,
            a,
            b,
            k: self.geometry.k,
            p0,
            m_used: mx,
            m_side: my,
            mu_used: mu,
            mu_force: mu_f,
            j1,
            j2,
            j3,
            j4,
            j5,
            j6,
            j7,
            regime,
            outside_envelope,
            temperature_rise,
        })
    }

    /// Solve the loaded contact (semi-axes `ab`) at slopes m_x, m_y and
    /// traction coefficients μ (J groups), μ_f (forces).
    fn solve(
        &self,
        state: &OperatingState,
        [a, b]: [f64; 2],
        [mx, my, mu, mu_f]: [f64; 4],
        accuracy: Accuracy,
    ) -> Result<Solved, ContactError> {
        let k = self.geometry.k;
        let n = state.load;
        let sqrt_ab = (a * b).sqrt();
        let sk = k.sqrt();
        let cx = 3.0 * PI / 8.0 * (mx / mu) * sk;
        let gy = my / mx;
        let u = state.rolling_speed;
        let uf = self.options.rolling_speed_floor;
        let u_eff = u.abs().max(uf);
        let t = (u / uf).clamp(-1.0, 1.0);
        let w = 0.5 + 0.75 * t - 0.25 * t * t * t;
        let rate = [
            cx * state.slip / u_eff,
            cx * state.side_slip / u_eff,
            cx * state.spin * sqrt_ab / u_eff,
        ];
        // Frame σ: (σ J1, σ J2, J3).
        let frame = |s: f64| [s * rate[0], s * rate[1], rate[2]];
        let fwd = if w > 0.0 {
            Some(self.branch(k, frame(1.0), gy, accuracy)?)
        } else {
            None
        };
        // Below the floor the reversed frame (−J1, −J2, J3) is taken from
        // (J1, −J2, J3): the models are odd in the slips (Z → −Z) and
        // symmetric about the rolling direction (Y → −Y), so its (J4, J5, J6)
        // are (−J4, J5, J6) there. Without side slip that is the forward
        // frame itself, evaluated once (docs/decisions/0111).
        let rev = if w < 1.0 {
            Some(match fwd {
                Some(f) => {
                    let b = if rate[1] == 0.0 {
                        f
                    } else {
                        self.branch(k, [rate[0], -rate[1], rate[2]], gy, accuracy)?
                    };
                    Branch {
                        j: frame(-1.0),
                        out: [-b.out[0], b.out[1], b.out[2]],
                    }
                }
                None => self.branch(k, frame(-1.0), gy, accuracy)?,
            })
        } else {
            None
        };
        // Lab-frame dimensionless forces: (σ J4_σ, σ J5_σ, J6_σ), blended.
        let mut lab = [0.0; 3];
        for (br, s, weight) in [(fwd, 1.0, w), (rev, -1.0, 1.0 - w)] {
            if let Some(br) = br {
                lab[0] += weight * s * br.out[0];
                lab[1] += weight * s * br.out[1];
                lab[2] += weight * br.out[2];
            }
        }
        let sigma = if w >= 0.5 { 1.0 } else { -1.0 };
        let dominant = if sigma > 0.0 { fwd } else { rev };
        let fx = mu_f * n * lab[0];
        let fy = mu_f * n * lab[1];
        let mz = mu_f * n * sqrt_ab * lab[2];
        let loss = (fx * state.slip + fy * state.side_slip + mz * state.spin).max(0.0);
        let j = frame(sigma);
        let (j4, j5, j6) = (sigma * lab[0], sigma * lab[1], lab[2]);
        let j7 = (j[0] * j4 + j[1] * j5 + j[2] * j6).max(0.0);
        finite_outputs(&[
            ("traction J4", j4),
            ("side force J5", j5),
            ("spin torque J6", j6),
            ("force fx (N)", fx),
            ("force fy (N)", fy),
            ("spin moment mz (N m)", mz),
        ])?;
        Ok(Solved {
            f: [fx, fy, mz],
            loss,
            j: [j[0], j[1], j[2], j4, j5, j6, j7],
            dominant,
        })
    }

    /// The open contact (N = 0): no forces, no ellipse.
    fn open(&self, _state: &OperatingState) -> Evaluation {
        let (m, mu, mu_f) = match self.fluid {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => (slope, peak, spin_peak.unwrap_or(peak)),
            // μ = τ̄πab/N and m are undefined at N = 0 (and the report
            // correlations need P0 > 0); reported as 0.
            Fluid::Physical { .. } | Fluid::Report { .. } => (0.0, 0.0, 0.0),
        };
        Evaluation {
            fx: 0.0,
            fy: 0.0,
            mz: 0.0,
            traction_x: 0.0,
            traction_y: 0.0,
            loss: 0.0,
            a: 0.0,
            b: 0.0,
            k: self.geometry.k,
            p0: 0.0,
            m_used: m,
            m_side: m,
            mu_used: mu,
            mu_force: mu_f,
            j1: 0.0,
            j2: 0.0,
            j3: 0.0,
            j4: 0.0,
            j5: 0.0,
            j6: 0.0,
            j7: 0.0,
            regime: if self.options.classify_regime {
                Regime::ElasticWithoutSpin
            } else {
                Regime::NotClassified
            },
            outside_envelope: OutsideEnvelope::default(),
            temperature_rise: 0.0,
        }
    }
}
