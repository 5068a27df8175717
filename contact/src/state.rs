//! The operating state of the contact and its builder.

use traction_kinematics::ContactKinematics;

use crate::error::{ContactError, check};
use crate::{MAX_LOAD, MAX_SPEED, MAX_SPIN};

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
    /// 0 ≤ load ≤ [`MAX_LOAD`]; |U|, |ΔU|, |ΔV| ≤ [`MAX_SPEED`];
    /// |ω| ≤ [`MAX_SPIN`]; θ finite and above −273.15 °C.
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
        check(
            "load N (normal load, N)",
            self.load,
            self.load >= 0.0 && self.load <= MAX_LOAD,
            "in [0, 1e12] N",
        )?;
        let speed = |q, v: f64| check(q, v, v.abs() <= MAX_SPEED, "finite, |value| ≤ 1e6 m/s");
        speed("rolling speed U (m/s)", self.rolling_speed)?;
        speed("slip ΔU (m/s)", self.slip)?;
        speed("side slip ΔV (m/s)", self.side_slip)?;
        check(
            "spin ω (rad/s)",
            self.spin,
            self.spin.abs() <= MAX_SPIN,
            "finite, |ω| ≤ 1e9 rad/s",
        )?;
        check(
            "inlet temperature θ (°C)",
            self.inlet_temperature_celsius,
            self.inlet_temperature_celsius > -273.15,
            "finite and above −273.15 °C",
        )?;
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
