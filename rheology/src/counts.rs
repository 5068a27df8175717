//! Step counts of the elastic/plastic strip integrator (feature
//! `step-counts`, for profiling; off by default, when the counting
//! compiles to nothing).
//!
//! Each thread counts the strips it integrates and the steps of their
//! plastic segments by kind, so that a cost can be split into strips ×
//! steps per strip and the steps by the rule that takes them. The
//! viscoelastic model's isotropic caps run on the same plastic stepping and
//! are counted with it; its strips and its own Rosenbrock step attempts are
//! counted apart.
//! The profiling drivers `xtask prof` and `xtask prof-visco`, built with
//! `--features step-counts`, print them per evaluation (docs/DEVELOPING.md).

#[cfg(feature = "step-counts")]
use std::cell::Cell;

/// Counts since the thread started or since [`reset_step_counts`].
#[cfg(feature = "step-counts")]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StepCounts {
    /// Strips integrated by the elastic/plastic strip integrator (the
    /// rigid/plastic model's are not counted).
    pub strips: u64,
    /// Yield (or reloading) points searched on elastic segments.
    pub yield_searches: u64,
    /// Steps of the stiff segments' loop (`Strip::advance`): one RK4 step,
    /// RK4 sub-steps, or the quasi-steady step.
    pub stiff_steps: u64,
    /// Classical RK4 steps, sub-steps included.
    pub rk4: u64,
    /// Of them, the sub-steps of stiff or turn-limited steps.
    pub rk4_sub_steps: u64,
    /// Steps of the six-stage fifth-order rule.
    pub rk5: u64,
    /// Exponential (ETDRK4) steps tried (where one does not apply, the RK4
    /// steps that replace it are counted too).
    pub exponential: u64,
    /// Rosenbrock steps on the lag tried in place of RK4 sub-steps (where
    /// one is not accurate enough, the sub-steps that replace it are
    /// counted too).
    pub rosenbrock: u64,
    /// Quasi-steady steps (those blended with sub-steps included).
    pub quasi_steady: u64,
    /// Unloading points located inside a step.
    pub unloadings: u64,
    /// Strips integrated by the viscoelastic model (`visco::strip`).
    pub visco_strips: u64,
    /// Rosenbrock step attempts of the viscoelastic strips (the interior,
    /// and the caps with an anisotropic stiffness), rejected ones included.
    pub visco_steps: u64,
}

#[cfg(feature = "step-counts")]
thread_local! {
    static COUNTS: Cell<StepCounts> = const {
        Cell::new(StepCounts {
            strips: 0,
            yield_searches: 0,
            stiff_steps: 0,
            rk4: 0,
            rk4_sub_steps: 0,
            rk5: 0,
            exponential: 0,
            rosenbrock: 0,
            quasi_steady: 0,
            unloadings: 0,
            visco_strips: 0,
            visco_steps: 0,
        })
    };
}

/// This thread's counts.
#[cfg(feature = "step-counts")]
pub fn step_counts() -> StepCounts {
    COUNTS.with(Cell::get)
}

/// Sets this thread's counts to zero.
#[cfg(feature = "step-counts")]
pub fn reset_step_counts() {
    COUNTS.with(|c| c.set(StepCounts::default()));
}

/// Adds one to a count of this thread.
#[cfg(feature = "step-counts")]
#[inline(always)]
pub(crate) fn bump(f: impl FnOnce(&mut StepCounts)) {
    COUNTS.with(|c| {
        let mut v = c.get();
        f(&mut v);
        c.set(v);
    });
}

/// Counts one event (`count!(rk4)`): nothing without the feature
/// `step-counts`.
macro_rules! count {
    ($field:ident) => {
        #[cfg(feature = "step-counts")]
        $crate::counts::bump(|c| c.$field += 1);
    };
}
pub(crate) use count;

#[cfg(all(test, feature = "step-counts"))]
mod tests {
    use super::*;
    use crate::{Inputs, Resolution, reference};

    #[test]
    fn counts_the_strips_and_steps_of_the_fixed_resolution_reference() {
        // The fixed-resolution reference integrates exactly panels × points
        // strips (3 × 4 = 12); case a of the bench set (k = 0.5,
        // J = (2, −1, 10)) has plastic segments on them, stiff ones among
        // them. The counts start from zero after a reset and the sub-steps
        // are part of the RK4 steps.
        reset_step_counts();
        assert_eq!(step_counts(), StepCounts::default());
        let inp = Inputs::new(0.5, 2.0, -1.0, 10.0).unwrap();
        let res = Resolution {
            y_panels: 3,
            y_points: 4,
            s_step: 0.1,
        };
        reference::elastic_plastic(&inp, &res).unwrap();
        let c = step_counts();
        assert_eq!(c.strips, 12, "{c:?}");
        assert!(
            c.yield_searches >= 12 && c.rk4 > 12 && c.stiff_steps > 0,
            "{c:?}"
        );
        assert!(c.rk4_sub_steps <= c.rk4, "{c:?}");
        // No exponential, fifth-order or Rosenbrock steps in the reference.
        assert_eq!((c.exponential, c.rk5, c.rosenbrock), (0, 0, 0), "{c:?}");
        reset_step_counts();
        assert_eq!(step_counts(), StepCounts::default());
    }

    #[test]
    fn counts_the_viscoelastic_strips_apart_from_their_caps_steps() {
        // The viscoelastic strips and their Rosenbrock attempts have counts
        // of their own (every strip takes at least one step); the caps of
        // an isotropic stiffness run on the elastic/plastic stepping and
        // count there, without counting as elastic/plastic strips; with
        // gy ≠ 1 the caps take Rosenbrock steps, so no plastic steps count.
        use crate::{Accuracy, Model, evaluate};
        let model = Model::Viscoelastic {
            deborah: 1.0,
            z0: 1.0,
        };
        let acc = Accuracy::new(1e-3).unwrap();
        reset_step_counts();
        // The high-spin viscoelastic bench case h, whose strips reach the cap.
        let inp = Inputs::new(5.0, 0.0, 3.368, 25.816).unwrap();
        evaluate(&inp, model, acc).unwrap();
        let c = step_counts();
        assert!(c.visco_strips > 0, "{c:?}");
        assert!(c.visco_steps >= c.visco_strips, "{c:?}");
        assert_eq!((c.strips, c.yield_searches), (0, 0), "{c:?}");
        assert!(c.rk4 + c.rk5 + c.exponential > 0, "{c:?}");
        reset_step_counts();
        let inp = inp.with_stiffness_ratio(2.0).unwrap();
        evaluate(&inp, model, acc).unwrap();
        let c = step_counts();
        assert!(
            c.visco_steps >= c.visco_strips && c.visco_strips > 0,
            "{c:?}"
        );
        assert_eq!(
            (c.rk4, c.rk5, c.exponential, c.stiff_steps),
            (0, 0, 0, 0),
            "{c:?}"
        );
        reset_step_counts();
    }
}
