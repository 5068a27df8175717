//! The shear stress field Z = τ/τ̄ of the elastic/plastic model on a grid
//! over the contact (for plots and for inspecting the flow pattern).
//!
//! Each grid row is one strip of the integrator behind [`crate::evaluate`]:
//! in elastic segments Z is the exact closed form; on the limit |Z| = L(X)
//! exactly and the direction angle is interpolated between the integrator's
//! steps (of [`crate::Accuracy::s_step`] in s, X = c·sin s) by the cubic
//! Hermite polynomial in s with the flow rule's rate θ' (isotropic:
//! (2/3)(v·t)) at both ends (fourth order in the step).

use std::f64::consts::PI;

use crate::ep::{Event, Scaled};
use crate::{Accuracy, Inputs, J_RIGID, RheologyError};

/// Largest number of grid points per direction.
pub const MAX_GRID: usize = 4000;

/// State of the lubricant at a grid point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointState {
    /// Outside the contact ellipse (Z = 0).
    Outside,
    /// Elastic (|Z| < L).
    Elastic,
    /// On the limit (|Z| = L = (3/2)√(1−X²−Y²)).
    Plastic,
}

/// The stress field on an nx × ny grid of cell centres over [−1, 1]²
/// (X = x/a along rolling, Y = y/b across), row-major: index j·nx + i for
/// (x\[i\], y\[j\]).
#[derive(Debug, Clone, PartialEq)]
pub struct StressField {
    /// X of the columns.
    pub x: Vec<f64>,
    /// Y of the rows.
    pub y: Vec<f64>,
    /// Zx = τx/τ̄ (0 outside the contact).
    pub zx: Vec<f64>,
    /// Zy = τy/τ̄ (0 outside the contact).
    pub zy: Vec<f64>,
    /// Elastic, plastic or outside.
    pub state: Vec<PointState>,
}

impl StressField {
    /// (Zx, Zy, state) at column i, row j.
    pub fn at(&self, i: usize, j: usize) -> Option<(f64, f64, PointState)> {
        if i >= self.x.len() || j >= self.y.len() {
            return None;
        }
        let q = j * self.x.len() + i;
        Some((self.zx[q], self.zy[q], self.state[q]))
    }

    /// Fraction of the contact's grid points that are on the limit.
    pub fn plastic_fraction(&self) -> f64 {
        let inside = self
            .state
            .iter()
            .filter(|s| **s != PointState::Outside)
            .count();
        let plastic = self
            .state
            .iter()
            .filter(|s| **s == PointState::Plastic)
            .count();
        if inside == 0 {
            0.0
        } else {
            plastic as f64 / inside as f64
        }
    }
}

/// The elastic/plastic stress field (the default model: Ḡ constant, limit
/// (3/2)τ̄√(1−X²−Y²)) on an nx × ny grid of cell centres, nx, ny in
/// 1..=[`MAX_GRID`]. For max|J| > [`J_RIGID`] the rigid/plastic field
/// Z = L·v/|v| is returned.
pub fn stress_field(
    inp: &Inputs,
    nx: usize,
    ny: usize,
    acc: Accuracy,
) -> Result<StressField, RheologyError> {
    inp.validate()?;
    for n in [nx, ny] {
        if !(1..=MAX_GRID).contains(&n) {
            return Err(RheologyError::Grid(n));
        }
    }
    let centre = |i: usize, n: usize| -1.0 + (2.0 * i as f64 + 1.0) / n as f64;
    let x: Vec<f64> = (0..nx).map(|i| centre(i, nx)).collect();
    let y: Vec<f64> = (0..ny).map(|j| centre(j, ny)).collect();
    let mut zx = vec![0.0; nx * ny];
    let mut zy = vec![0.0; nx * ny];
    let mut state = vec![PointState::Outside; nx * ny];
    let jmax = inp.j1.abs().max(inp.j2.abs()).max(inp.j3.abs());
    let rigid = jmax > J_RIGID;
    let f = if rigid { 1.0 / jmax } else { 1.0 };
    let sc = Scaled::new(inp.k, inp.j1 * f, inp.j2 * f, inp.j3 * f, inp.dx).with_gy(inp.gy);
    let h = acc.s_step();
    let mut events = Vec::new();
    for (j, &yj) in y.iter().enumerate() {
        let st = sc.strip(yj);
        let c = st.c;
        if !rigid {
            events.clear();
            st.integrate_rec(h, 2.0 * h, &mut |e| events.push(e));
        }
        let mut k = 0;
        for (i, &xi) in x.iter().enumerate() {
            if xi.abs() >= c {
                continue;
            }
            let q = j * nx + i;
            let l = 1.5 * (c * c - xi * xi).sqrt();
            if rigid {
                let (vx, vy) = (st.a, (st.b1 + st.q2 * xi) / st.gy);
                let m = vx.hypot(vy);
                if m > 0.0 {
                    (zx[q], zy[q]) = (l * vx / m, l * vy / m);
                }
                state[q] = PointState::Plastic;
                continue;
            }
            // Advance to the event covering xi (events are ordered in X).
            while k < events.len() {
                let covers = match (events[k], events.get(k + 1)) {
                    (Event::Elastic { x1, .. }, _) => xi <= x1,
                    (Event::Plastic { .. }, Some(Event::Plastic { x, .. })) => xi <= *x,
                    (Event::Plastic { x, .. }, _) => xi <= x,
                };
                if covers {
                    break;
                }
                k += 1;
            }
            match (events.get(k), events.get(k + 1)) {
                (Some(&Event::Elastic { x0, z0, .. }), _) => {
                    (zx[q], zy[q]) = st.z_el(x0, z0, xi);
                    state[q] = PointState::Elastic;
                }
                (
                    Some(&Event::Plastic { x: xa, n: na }),
                    Some(&Event::Plastic { x: xb, n: nb }),
                ) => {
                    // Cubic Hermite in s (X = c·sin s) on the direction angle,
                    // with θ' = dθ/ds = (2/3)(v·t) at both ends.
                    let sa = (xa / c).clamp(-1.0, 1.0).asin();
                    let sb = (xb / c).clamp(-1.0, 1.0).asin();
                    let si = (xi / c).clamp(-1.0, 1.0).asin();
                    let ta = na.1.atan2(na.0);
                    let mut d = nb.1.atan2(nb.0) - ta;
                    if d > PI {
                        d -= 2.0 * PI;
                    } else if d < -PI {
                        d += 2.0 * PI;
                    }
                    let rate = |x: f64, n: (f64, f64)| {
                        let sn = (x / c).clamp(-1.0, 1.0);
                        st.theta_rate(sn, (1.0 - sn * sn).max(0.0).sqrt(), n.0, n.1)
                    };
                    let hs = sb - sa;
                    let th = if hs > 0.0 {
                        let t = ((si - sa) / hs).clamp(0.0, 1.0);
                        let (t2, t3) = (t * t, t * t * t);
                        ta + (3.0 * t2 - 2.0 * t3) * d
                            + (t3 - 2.0 * t2 + t) * hs * rate(xa, na)
                            + (t3 - t2) * hs * rate(xb, nb)
                    } else {
                        ta
                    };
                    let (s, co) = th.sin_cos();
                    (zx[q], zy[q]) = (l * co, l * s);
                    state[q] = PointState::Plastic;
                }
                (Some(&Event::Plastic { n, .. }), _) => {
                    (zx[q], zy[q]) = (l * n.0, l * n.1);
                    state[q] = PointState::Plastic;
                }
                (None, _) => {}
            }
        }
    }
    Ok(StressField {
        x,
        y,
        zx,
        zy,
        state,
    })
}
