//! Workspace-wide golden tests against the report's printed tables.
//!
//! The tests live in `tests/tests/*.rs`, one file per group of tables. This
//! library only holds small helpers shared by them.
#![forbid(unsafe_code)]

/// Relative difference `|computed - printed| / |printed|`, or the absolute
/// difference when the printed value is zero.
pub fn rel_diff(computed: f64, printed: f64) -> f64 {
    if printed == 0.0 {
        (computed - printed).abs()
    } else {
        ((computed - printed) / printed).abs()
    }
}

/// Maximum and root-mean-square of a set of deviations.
pub fn max_rms(devs: &[f64]) -> (f64, f64) {
    if devs.is_empty() {
        return (0.0, 0.0);
    }
    let max = devs.iter().fold(0.0_f64, |m, d| m.max(d.abs()));
    let rms = (devs.iter().map(|d| d * d).sum::<f64>() / devs.len() as f64).sqrt();
    (max, rms)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rel_diff_and_max_rms() {
        assert!((rel_diff(1.01, 1.0) - 0.01).abs() < 1e-12);
        assert_eq!(rel_diff(0.5, 0.0), 0.5);
        let (m, r) = max_rms(&[3.0, -4.0]);
        assert_eq!(m, 4.0);
        assert!((r - (12.5_f64).sqrt()).abs() < 1e-12);
    }
}
