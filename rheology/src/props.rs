//! The other property variations App. IV discusses (eq. 8 and the text after
//! it): shear modulus constant or pressure-proportional, limiting shear
//! stress pressure-proportional or constant, both normalised to the same
//! means Ḡ and τ̄:
//!
//! * G = Ḡ or G = (3/2)Ḡ√(1−X²−Y²) (the elastic rate is multiplied by
//!   g = G/Ḡ);
//! * τ_lim = (3/2)τ̄√(1−X²−Y²) (L as in the default) or τ_lim = τ̄ (L = 1).
//!
//! The default (G constant, τ_lim pressure-proportional) is what the report's
//! printed theory uses and is solved by the fast strip integrator. The other
//! combinations are solved here by a plain grid scheme (elastic predictor
//! with the exact integral of v over the cell, return onto L (radial; the
//! energy-norm closest point for a stiffness ratio gy ≠ 1), strips in
//! Y = sin φ), first order in the cell size, Richardson-extrapolated from n
//! and 2n cells per strip. Slow (milliseconds) but robust; its accuracy is
//! ≈ 1e-4 at n = 800, checked in the tests against the strip integrator for
//! the default combination and against a closed form for L = 1.

use std::f64::consts::PI;

use crate::ep::{Scaled, return_map};

/// Variation of the shear modulus over the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Modulus {
    /// G = Ḡ everywhere (the report's choice; absorbs roller compliance).
    #[default]
    Constant,
    /// G = (3/2)Ḡ√(1−X²−Y²), proportional to the Hertz pressure.
    PressureProportional,
}

/// Variation of the limiting shear stress over the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Limit {
    /// τ_lim = (3/2)τ̄√(1−X²−Y²) (the report's choice).
    #[default]
    PressureProportional,
    /// τ_lim = τ̄ everywhere.
    Constant,
}

/// Property variation: which of App. IV's combinations to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Properties {
    /// Shear modulus variation.
    pub modulus: Modulus,
    /// Limiting shear stress variation.
    pub limit: Limit,
}

fn grid(sc: &Scaled, props: Properties, n: usize) -> (f64, f64, f64) {
    let (mut s4, mut s5, mut sxy, mut syx) = (0.0, 0.0, 0.0, 0.0);
    for i in 0..n {
        let phi = -PI / 2.0 + PI * (i as f64 + 0.5) / n as f64;
        let (y, c) = phi.sin_cos();
        let wy = PI / n as f64 * c;
        let st = sc.strip(y);
        let h = 2.0 * c / n as f64;
        let (mut zx, mut zy) = (0.0_f64, 0.0_f64);
        let (mut ix, mut iy, mut ixy) = (0.0, 0.0, 0.0);
        for j in 0..n {
            let x0 = -c + h * j as f64;
            let x1 = x0 + h;
            let (ox, oy) = (zx, zy);
            match props.modulus {
                Modulus::Constant => {
                    zx += st.a * h;
                    zy += (st.b1 + st.q2 * 0.5 * (x0 + x1)) * h;
                }
                Modulus::PressureProportional => {
                    // ∫ g·v dX over the cell by 2-point Gauss.
                    let xm = 0.5 * (x0 + x1);
                    let d = 0.5 * h / 3f64.sqrt();
                    for xg in [xm - d, xm + d] {
                        let g = 1.5 * (c * c - xg * xg).max(0.0).sqrt();
                        zx += 0.5 * h * g * st.a;
                        zy += 0.5 * h * g * (st.b1 + st.q2 * xg);
                    }
                }
            }
            let l = match props.limit {
                Limit::PressureProportional => 1.5 * (c * c - x1 * x1).max(0.0).sqrt(),
                Limit::Constant => 1.0,
            };
            (zx, zy) = return_map(zx, zy, l, st.gy);
            ix += 0.5 * h * (ox + zx);
            iy += 0.5 * h * (oy + zy);
            ixy += 0.5 * h * (oy * x0 + zy * x1);
        }
        s4 += wy * ix;
        s5 += wy * iy;
        sxy += wy * ixy;
        syx += wy * y * ix;
    }
    (
        s4 / PI,
        s5 / PI,
        (sxy + sc.dx * s5 - sc.k * syx) / (PI * sc.k.sqrt()),
    )
}

/// Richardson-extrapolated grid solution with n and 2n cells per strip.
pub(crate) fn solve(sc: &Scaled, props: Properties, n: usize) -> (f64, f64, f64) {
    let a = grid(sc, props, n);
    let b = grid(sc, props, 2 * n);
    (2.0 * b.0 - a.0, 2.0 * b.1 - a.1, 2.0 * b.2 - a.2)
}
