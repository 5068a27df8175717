//! The operating state of the contact and its builder.

use traction_kinematics::ContactKinematics;

use crate::error::ContactError;
use crate::{INLET_TEMPERATURE_RANGE, LOAD_RANGE, SPEED_RANGE, SPIN_RANGE};

/// An operating state of the contact (SI units, lab frame, signs as in the crate docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingState {
    /// Normal load N, N (0 = contact open).
    pub load: f64,
    /// Rolling speed U = ½(v₁ + v₂)·x, m/s (either sign).
    pub rolling_speed: f64,
    /// Slip ΔU = (v₁ − v₂)·x, m/s.
    pub slip: f64,
    /// Side slip ΔV = (v₁ − v₂)·y, m/s.
    pub side_slip: f64,
    /// Spin ω = (Ω₁ − Ω₂)·z, rad/s.
    pub spin: f64,
    /// Inlet temperature θ, °C (used by temperature-dependent fluids).
    pub inlet_temperature_celsius: f64,
}

impl OperatingState {
    /// A state by named quantities: load and inlet temperature required,
    /// U, ΔU, ΔV, ω zero unless set.
    ///
    /// ```
    /// use traction_contact::OperatingState;
    /// let s = OperatingState::builder()
    ///     .load(5000.0)
    ///     .rolling_speed(80.0)
    ///     .side_slip(0.65)
    ///     .spin(35.0)
    ///     .inlet_temperature_celsius(73.0)
    ///     .build()?;
    /// assert_eq!(s.slip, 0.0);
    /// # Ok::<(), traction_contact::ContactError>(())
    /// ```
    pub fn builder() -> OperatingStateBuilder {
        OperatingStateBuilder::default()
    }

    /// A checked state from positional values (load N, U, ΔU, ΔV, ω,
    /// θ °C); [`OperatingState::builder`] names them. Checks:
    /// load in [`LOAD_RANGE`]; U, ΔU, ΔV in [`SPEED_RANGE`]; ω in
    /// [`SPIN_RANGE`]; θ in [`INLET_TEMPERATURE_RANGE`].
    pub fn new(
        load: f64,
        rolling_speed: f64,
        slip: f64,
        side_slip: f64,
        spin: f64,
        inlet_temperature_celsius: f64,
    ) -> Result<Self, ContactError> {
        let s = OperatingState {
            load,
            rolling_speed,
            slip,
            side_slip,
            spin,
            inlet_temperature_celsius,
        };
        s.validate()?;
        Ok(s)
    }

    /// The state from the bodies' motion at the contact (traction-kinematics:
    /// U, ΔU, ΔV, ω in the same sign convention as this crate).
    pub fn from_kinematics(
        kinematics: &ContactKinematics,
        load: f64,
        inlet_temperature_celsius: f64,
    ) -> Result<Self, ContactError> {
        OperatingState::builder()
            .load(load)
            .rolling_speed(kinematics.rolling_speed)
            .slip(kinematics.slip)
            .side_slip(kinematics.side_slip)
            .spin(kinematics.spin)
            .inlet_temperature_celsius(inlet_temperature_celsius)
            .build()
    }

    /// Check the ranges (the fields are public, so [`TractionContact::evaluate`](crate::TractionContact::evaluate) checks again).
    pub fn validate(&self) -> Result<(), ContactError> {
        LOAD_RANGE.check("load N (normal load)", self.load)?;
        SPEED_RANGE.check("rolling speed U", self.rolling_speed)?;
        SPEED_RANGE.check("slip ΔU", self.slip)?;
        SPEED_RANGE.check("side slip ΔV", self.side_slip)?;
        SPIN_RANGE.check("spin ω", self.spin)?;
        INLET_TEMPERATURE_RANGE.check("inlet temperature θ", self.inlet_temperature_celsius)?;
        Ok(())
    }
}

/// Builder of an [`OperatingState`] by named quantities (SI units).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct OperatingStateBuilder {
    load: Option<f64>,
    rolling_speed: f64,
    slip: f64,
    side_slip: f64,
    spin: f64,
    inlet_temperature_celsius: Option<f64>,
}

impl OperatingStateBuilder {
    /// Normal load N, N (required).
    pub fn load(mut self, load: f64) -> Self {
        self.load = Some(load);
        self
    }
    /// Rolling speed U, m/s (default 0).
    pub fn rolling_speed(mut self, u: f64) -> Self {
        self.rolling_speed = u;
        self
    }
    /// Slip ΔU = (v₁ − v₂)·x, m/s (default 0).
    pub fn slip(mut self, du: f64) -> Self {
        self.slip = du;
        self
    }
    /// Side slip ΔV = (v₁ − v₂)·y, m/s (default 0).
    pub fn side_slip(mut self, dv: f64) -> Self {
        self.side_slip = dv;
        self
    }
    /// Spin ω = (Ω₁ − Ω₂)·z, rad/s (default 0).
    pub fn spin(mut self, omega: f64) -> Self {
        self.spin = omega;
        self
    }
    /// Inlet temperature θ, °C (required).
    pub fn inlet_temperature_celsius(mut self, theta: f64) -> Self {
        self.inlet_temperature_celsius = Some(theta);
        self
    }
    /// The checked state (ranges as [`OperatingState::new`]); a missing load
    /// or inlet temperature is an error naming it.
    pub fn build(self) -> Result<OperatingState, ContactError> {
        let missing = |quantity| ContactError::OutOfRange {
            quantity,
            value: f64::NAN,
            valid: "required: set it on the builder",
        };
        OperatingState::new(
            self.load.ok_or(missing("load N (normal load, N)"))?,
            self.rolling_speed,
            self.slip,
            self.side_slip,
            self.spin,
            self.inlet_temperature_celsius
                .ok_or(missing("inlet temperature θ (°C)"))?,
        )
    }
}
