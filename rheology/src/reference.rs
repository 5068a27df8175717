//! Reference solutions for tests and convergence studies: the strip
//! integrator at an explicit, fixed resolution and the independent grid
//! scheme. [`crate::evaluate`] is the API for applications.

use crate::{Inputs, Outputs, Properties, Resolution, RheologyError, ep, finish};

/// Elastic/plastic strip integration (RK4 on the plastic segments, see
/// `ep.rs`) at an explicit, fixed resolution: `y_panels` × `y_points`
/// Gauss–Legendre strips in φ (Y = sin φ) and the s-step `s_step`. No
/// closed-form fast path; max|J| > [`crate::J_RIGID`] returns the
/// rigid/plastic solution.
pub fn elastic_plastic(inp: &Inputs, res: &Resolution) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    let m = inp.j1.abs().max(inp.j2.abs()).max(inp.j3.abs());
    if m > crate::J_RIGID {
        return crate::rigid_plastic(inp, crate::Accuracy { tol: 1e-6 });
    }
    let sc = ep::Scaled::of(inp);
    let (j4, j5, j6) = ep::solve(&sc, res);
    Ok(finish(inp, j4, j5, j6))
}

/// The grid scheme of [`crate::props`] for any property combination, with
/// `cells` and 2·`cells` cells per strip (and as many strips),
/// Richardson-extrapolated (clamped to 10..=20000). Independent of the
/// strip integrator; used to cross-check it.
pub fn grid(inp: &Inputs, props: Properties, cells: usize) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    let sc = ep::Scaled::of(inp);
    let (j4, j5, j6) = crate::props::solve(&sc, props, cells.clamp(10, 20000));
    Ok(finish(inp, j4, j5, j6))
}

/// The viscoelastic model of [`crate::evaluate`] at the accuracy
/// `acc.tol` with the former panel rule across Y: 4-point Gauss–Legendre
/// panels, each accepted when its value and the sum over its two halves
/// differ by less than tol·width/π (12 strips per accepted initial panel,
/// against 5 of the Lobatto–Kronrod rule of `evaluate`); the same strips
/// and initial panels. For tests and cost comparisons
/// (`cargo xtask prof-visco CASE TOL REPS gauss`).
pub fn viscoelastic_gauss_panels(
    inp: &Inputs,
    deborah: f64,
    z0: f64,
    acc: crate::Accuracy,
) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    crate::check_viscoelastic(deborah, z0)?;
    let sc = ep::Scaled::of(inp);
    let law = crate::visco::Law::new(z0, deborah);
    let (j4, j5, j6) = crate::visco::solve_gauss_panels(&sc, law, acc.tol);
    Ok(finish(inp, j4, j5, j6))
}

/// The former viscoelastic integrator (sinh law with the limit as a cap,
/// [`crate::Model::Viscoelastic`]) at an explicit, fixed resolution:
/// `res.y_panels` × `res.y_points` Gauss–Legendre strips in φ and `nsteps`
/// uniform steps in s per strip (exponential midpoint steps, a return onto
/// the cap, trapezoidal sums: second order in the interior, first order
/// where the cap is active; `res.s_step` is not used). Independent of the
/// adaptive solver of [`crate::evaluate`]; for tests and convergence
/// studies. D and Z0 are checked as by `evaluate`; D = ∞ is integrated
/// too (no viscous term).
pub fn viscoelastic(
    inp: &Inputs,
    deborah: f64,
    z0: f64,
    res: &Resolution,
    nsteps: usize,
) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    crate::check_viscoelastic(deborah, z0)?;
    let sc = ep::Scaled::of(inp);
    let law = crate::visco::Law::new(z0, deborah);
    let (j4, j5, j6) = crate::visco::reference::solve(&sc, law, res, nsteps.clamp(1, 1_000_000));
    Ok(finish(inp, j4, j5, j6))
}
