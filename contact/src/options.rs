//! Evaluation options and the disc-compliance correction.

use crate::thermal::Thermal;
use crate::{Accuracy, DEFAULT_ROLLING_SPEED_FLOOR, Direction, DiscMaterial, Model, Properties};

/// Disc-compliance correction of the traction slope (App. IV appendices A, B).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Compliance {
    /// No correction: the one slope m scales J1, J2 and J3.
    #[default]
    Off,
    /// The discs are elastic (`material`, both discs alike), with Kalker's
    /// q_x = π/C11, q_y = π/C22 at this contact's k (traction-compliance).
    ///
    /// * [`Fluid::Constant`](crate::Fluid::Constant): m is the slope *measured* in `slope_measured_in`
    ///   on this contact (the report measured side-slip slopes); the slope of
    ///   the other direction follows from App. IV eq. B7 at the same contact
    ///   and P0 (the Table 4-3 operation).
    /// * [`Fluid::Physical`](crate::Fluid::Physical): Ḡ is the film's own modulus; each direction's
    ///   slope is the film and the discs in series (App. IV A3):
    ///   1/m_i = 1/m_film + 1/m'_i with the dry slope m'_i = 3G_s/(2 q_i P0) (B3).
    ///   `slope_measured_in` is not used.
    Discs {
        /// Disc material (E, ν; ν within Kalker's table, 0..0.5).
        material: DiscMaterial,
        /// Direction in which the user's slope m was measured.
        slope_measured_in: Direction,
    },
}

/// Evaluation options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Constitutive model (default elastic/plastic, the report's).
    pub model: Model,
    /// Accuracy of the rheology integration (absolute, in J4, J5, J6).
    pub accuracy: Accuracy,
    /// Disc-compliance correction of the slope.
    pub compliance: Compliance,
    /// Rolling-speed floor U_f of the J groups, m/s, in
    /// [`ROLLING_SPEED_FLOOR_RANGE`](crate::ROLLING_SPEED_FLOOR_RANGE) (see crate docs).
    pub rolling_speed_floor: f64,
    /// Classify the regime of App. IV figure 14 (costs a rigid/plastic
    /// evaluation when spin is present).
    pub classify_regime: bool,
    /// Distribution of the shear modulus and of the limiting shear stress
    /// over the contact (App. IV eq. 8 and the text after it), for the
    /// elastic/plastic model. The default (Ḡ constant, limit ∝ pressure) is
    /// the report's and uses the fast strip integrator; the others use the
    /// rheology crate's grid scheme (≈ 1e-4, milliseconds per evaluation).
    pub properties: Properties,
    /// Evaluate the elastic/plastic model through a lazily built
    /// interpolation map ([`traction_rheology::map::Map`], one per contact, at
    /// the same accuracy) instead of integrating the strips at every call.
    /// Used when the map applies: the default property distribution, the
    /// accuracy in the map's range
    /// ([`traction_rheology::map::TOLERANCE_RANGE`]) and gy = 1 (no
    /// compliance correction; with it gy = m_y/m_x changes with the load);
    /// otherwise direct. Pays off for
    /// many evaluations in a region of (J1, J2, J3) — a co-simulation near an
    /// operating point: ≈ 0.2 µs instead of 10–700 µs. The map spends within
    /// [`Budget::DEFAULT`](crate::Budget::DEFAULT): each evaluation earns 0.5
    /// node evaluations of credit, a new cell is built only when the credit
    /// covers it and a state whose cell is not built is evaluated directly,
    /// so on any sequence of states the map costs at most a few direct
    /// evaluations per evaluation (measured 1.5–1.7× on scattered states
    /// with spin), and a new map's first evaluations are direct. Results are
    /// within the accuracy of the direct ones either way but depend on the
    /// calls before (the same sequence gives the same results; crate
    /// README, docs/decisions/0078). Default off.
    pub map: bool,
    /// The thermal model ([`crate::thermal`]): the film's temperature rise
    /// from the contact's own dissipation, and μ, m at that temperature,
    /// solved self-consistently; reported in [`crate::Evaluation::temperature_rise`].
    /// Default `None`: isothermal, the report's theory.
    pub thermal: Option<Thermal>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            model: Model::ElasticPlastic,
            accuracy: Accuracy::default(),
            compliance: Compliance::Off,
            rolling_speed_floor: DEFAULT_ROLLING_SPEED_FLOOR,
            classify_regime: true,
            properties: Properties::default(),
            map: false,
            thermal: None,
        }
    }
}
