//! The result of a call on the safe side of an FMU, where an instance sends
//! its warnings, and the states of the FMI 2 co-simulation state machine.
//! The C boundary ([`crate::ffi`]) turns a [`Status`] into an `fmi2Status`
//! and an [`FmuError`] into a logged message.

use crate::xml::{LOG_STATUS_ERROR, LOG_STATUS_FATAL, LOG_STATUS_WARNING};

/// Status of a call, mirroring `fmi2Status` (ordered by severity).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    /// fmi2OK.
    Ok = 0,
    /// fmi2Warning.
    Warning = 1,
    /// fmi2Discard.
    Discard = 2,
    /// fmi2Error.
    Error = 3,
    /// fmi2Fatal.
    Fatal = 4,
}

impl Status {
    /// The log category of a failure or warning of this status:
    /// `logStatusFatal`, `logStatusWarning`, else `logStatusError`.
    pub fn category(self) -> &'static str {
        match self {
            Status::Fatal => LOG_STATUS_FATAL.0,
            Status::Warning => LOG_STATUS_WARNING.0,
            _ => LOG_STATUS_ERROR.0,
        }
    }
}

/// A failed call: status (Error or Fatal) and the message to log.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct FmuError {
    /// fmi2Error or fmi2Fatal.
    pub status: Status,
    /// What went wrong, naming the function, variable or quantity.
    pub message: String,
}

impl FmuError {
    /// An fmi2Error with a message.
    pub fn error(message: impl Into<String>) -> Self {
        Self {
            status: Status::Error,
            message: message.into(),
        }
    }
}

/// Result of a model call: `Ok(Status::Ok | Status::Warning)` or an error.
pub type FmuResult = Result<Status, FmuError>;

/// Where a model sends warnings (the host's logger behind the C boundary).
pub trait Logger {
    /// Logs one message under an FMI log category.
    fn log(&mut self, status: Status, category: &str, message: &str);
}

/// A logger that drops everything (tests, benches).
#[derive(Debug, Default, Clone, Copy)]
pub struct NullLogger;

impl Logger for NullLogger {
    fn log(&mut self, _: Status, _: &str, _: &str) {}
}

/// States of the FMI 2 co-simulation state machine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// After fmi2Instantiate or fmi2Reset.
    Instantiated = 0,
    /// Between fmi2EnterInitializationMode and fmi2ExitInitializationMode.
    Initialization = 1,
    /// Initialized; steps may be taken.
    StepComplete = 2,
    /// After fmi2Terminate.
    Terminated = 3,
    /// After a call returned fmi2Error.
    Error = 4,
    /// After a call returned fmi2Fatal: only fmi2FreeInstance remains.
    Fatal = 5,
}

impl Mode {
    /// Every mode but the fatal one (fmi2Reset, fmi2SetFMUstate).
    pub const NOT_FATAL: &'static [Mode] = &[
        Mode::Instantiated,
        Mode::Initialization,
        Mode::StepComplete,
        Mode::Terminated,
        Mode::Error,
    ];
    /// Where the fmi2Get{Real,Integer,Boolean} of the FMI 2.0 co-simulation
    /// state machine are allowed.
    pub const GET: &'static [Mode] = &[
        Mode::Initialization,
        Mode::StepComplete,
        Mode::Terminated,
        Mode::Error,
    ];
    /// Where a fixed parameter may be set.
    pub const SET_PARAMETER: &'static [Mode] = &[Mode::Instantiated, Mode::Initialization];
    /// Where an input may be set.
    pub const SET_INPUT: &'static [Mode] =
        &[Mode::Instantiated, Mode::Initialization, Mode::StepComplete];

    /// The mode of a code (`mode as u8`); `None` for any other byte. Which
    /// modes a saved FMU state may hold is each FMU's own rule.
    pub fn from_code(c: u8) -> Option<Self> {
        Some(match c {
            0 => Mode::Instantiated,
            1 => Mode::Initialization,
            2 => Mode::StepComplete,
            3 => Mode::Terminated,
            4 => Mode::Error,
            5 => Mode::Fatal,
            _ => return None,
        })
    }

    /// Whether the call `func` is allowed in this mode: `Ok` when the mode
    /// is one of `allowed`; in the fatal mode an fmi2Fatal error (only
    /// fmi2FreeInstance remains), else an fmi2Error naming the mode and the
    /// allowed ones. The caller enters its error state with the error.
    ///
    /// # Errors
    /// As above.
    pub fn check(self, func: &str, allowed: &[Mode]) -> Result<(), FmuError> {
        if allowed.contains(&self) {
            Ok(())
        } else if self == Mode::Fatal {
            Err(FmuError {
                status: Status::Fatal,
                message: format!(
                    "{func}: the instance had a fatal error; only fmi2FreeInstance is allowed"
                ),
            })
        } else {
            Err(FmuError::error(format!(
                "{func}: not allowed in state {self:?} (allowed: {allowed:?})"
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn status_codes_and_order_are_fmi2s() {
        // fmi2Status: fmi2OK = 0 ... fmi2Fatal = 4 (FMI 2.0.x, fmi2FunctionTypes.h).
        let codes = [
            Status::Ok,
            Status::Warning,
            Status::Discard,
            Status::Error,
            Status::Fatal,
        ]
        .map(|s| s as i32);
        assert_eq!(codes, [0, 1, 2, 3, 4]);
        assert!(Status::Warning < Status::Error && Status::Error < Status::Fatal);
        assert_eq!(Status::Fatal.category(), "logStatusFatal");
        assert_eq!(Status::Warning.category(), "logStatusWarning");
        assert_eq!(Status::Error.category(), "logStatusError");
        let e = FmuError::error("x out of range");
        assert_eq!(
            (e.status, e.to_string()),
            (Status::Error, "x out of range".into())
        );
    }

    #[test]
    fn modes_round_trip_their_codes_and_check_calls() {
        for c in 0..=5 {
            assert_eq!(Mode::from_code(c).map(|m| m as u8), Some(c));
        }
        assert_eq!(Mode::from_code(6), None);
        let allowed = [Mode::Initialization, Mode::StepComplete];
        assert_eq!(Mode::StepComplete.check("fmi2DoStep", &allowed), Ok(()));
        let e = Mode::Instantiated
            .check("fmi2DoStep", &allowed)
            .unwrap_err();
        assert_eq!(e.status, Status::Error);
        assert_eq!(
            e.message,
            "fmi2DoStep: not allowed in state Instantiated (allowed: [Initialization, StepComplete])"
        );
        let f = Mode::Fatal.check("fmi2DoStep", &allowed).unwrap_err();
        assert_eq!(f.status, Status::Fatal);
        assert!(f.message.contains("only fmi2FreeInstance"));
        // The FMI 2.0 co-simulation state machine: getters from initialization
        // on, also in the error state; nothing but fmi2FreeInstance when fatal.
        assert!(!Mode::NOT_FATAL.contains(&Mode::Fatal) && Mode::NOT_FATAL.len() == 5);
        assert!(!Mode::GET.contains(&Mode::Instantiated) && Mode::GET.contains(&Mode::Error));
        assert!(!Mode::SET_PARAMETER.contains(&Mode::StepComplete));
        assert!(Mode::SET_INPUT.contains(&Mode::StepComplete));
    }
}
