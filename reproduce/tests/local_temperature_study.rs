//! Lumped or local temperature: the measured evidence behind the thermal
//! contact's contact-mean rise (docs/decisions/0025).
//!
//! A local temperature field is solved here on a plain grid scheme of the
//! elastic/plastic J+T model (the scheme of `traction_rheology::props`,
//! written out so that the limit can vary point by point): strips in
//! Y = sin φ, cells along X, the elastic predictor with the exact integral of
//! the sliding rate over the cell and a radial return onto the limit
//! f·(3/2)√(1 − X² − Y²). The limit factor f = μ(ΔT)/μ is the contact's own
//! temperature law at the local rise
//!
//!   ΔT(X, Y) = H·[φ_f·q(X, Y) + (1 − φ_f)·S[q](X, Y)/N],
//!
//! q = Z·v the local rate of work of the stress on the sliding (dimensionless),
//! φ_f the film's share of the contact's thermal resistance (conduction across
//! the film, local), S[q](X) = ∫ q(X′)/√(X − X′) dX′ over the strip upstream of
//! X the flash temperature of a surface moving under a band source at high
//! Péclet number (Jaeger; heat conducts into the surface normal to it only, so
//! strips are independent), N the area mean of S for a uniform source (so a
//! uniform q gives the same mean rise as the lumped model), and H the rise per
//! unit mean q of the lumped contact at the same state (its rise divided by
//! the grid's mean q at its converged factor). With a uniform f the grid
//! reproduces the contact's lumped prediction, which checks the whole chain.
#![allow(clippy::unwrap_used)] // test: a failed unwrap is a failed test

use std::f64::consts::PI;

use traction_reproduce::data::{APPENDIX_VI, DataTable};
use traction_reproduce::thermal::{self, Law};

/// Cells per strip and strips (first order in 1/N: 0.005 of J5 at 160 against
/// the strip integrator on these states).
const N: usize = 160;
/// The film's share of the contact's resistance at 80 m/s (≈ 85 %,
/// contact/README.md "Thermal model").
const FILM_SHARE: f64 = 0.85;

/// How the limit factor is set over the contact.
#[derive(Clone, Copy)]
enum Field<'a> {
    /// One factor everywhere.
    Uniform(f64),
    /// The local rise through the law `f(ΔT)` with rise per unit q `h`.
    Local { h: f64, law: &'a dyn Fn(f64) -> f64 },
}

/// (J5, area mean of q) of the grid scheme on a contact of aspect ratio k,
/// J groups at the inlet μ (ΔX = 0, isotropic stiffness).
fn grid(k: f64, j: [f64; 3], field: Field) -> (f64, f64) {
    let sk = k.sqrt();
    // N: area mean of S for q = 1, S = 2√(X + c), over the unit circle.
    let mut norm = 0.0;
    for i in 0..N {
        let c = (-PI / 2.0 + PI * (i as f64 + 0.5) / N as f64).cos();
        norm += (PI / N as f64) * c * 2.0 * c * (4.0 / 3.0) * (2.0 * c).sqrt();
    }
    norm /= PI;
    let (mut s5, mut qsum) = (0.0, 0.0);
    let mut q = vec![0.0; N];
    let mut xm = vec![0.0; N];
    for i in 0..N {
        let (y, c) = (-PI / 2.0 + PI * (i as f64 + 0.5) / N as f64).sin_cos();
        let wy = PI / N as f64 * c;
        // Sliding rate along the strip: (J1/√k − J3·Y, J2/√k + (J3/k)·X).
        let (a, b1, q2) = (j[0] / sk - j[2] * y, j[1] / sk, j[2] / k);
        let h = 2.0 * c / N as f64;
        let (mut zx, mut zy, mut iy) = (0.0_f64, 0.0_f64, 0.0);
        for n in 0..N {
            let x0 = -c + h * n as f64;
            let x1 = x0 + h;
            xm[n] = 0.5 * (x0 + x1);
            let oy = zy;
            let (vx, vy) = (a, b1 + q2 * xm[n]);
            let (tx, ty) = (zx + vx * h, zy + vy * h);
            let limit = 1.5 * (c * c - x1 * x1).max(0.0).sqrt();
            let ret = |f: f64| {
                let (t, l) = ((tx * tx + ty * ty).sqrt(), f * limit);
                if t > l {
                    (tx * l / t, ty * l / t)
                } else {
                    (tx, ty)
                }
            };
            (zx, zy) = match field {
                Field::Uniform(f) => ret(f),
                Field::Local { h: rise, law } => {
                    let upstream: f64 = (0..n).map(|m| q[m] * h / (xm[n] - xm[m]).sqrt()).sum();
                    // Fixed point of the cell's factor (damped; converges in
                    // a few iterations, the factor changes by < 1e-4).
                    let mut f = 1.0;
                    let mut z = ret(f);
                    for _ in 0..12 {
                        let qn = z.0 * vx + z.1 * vy;
                        let s = (upstream + qn * 2.0 * (0.5 * h).sqrt()) / norm;
                        f = 0.5 * f + 0.5 * law(rise * (FILM_SHARE * qn + (1.0 - FILM_SHARE) * s));
                        z = ret(f);
                    }
                    z
                }
            };
            q[n] = zx * vx + zy * vy;
            qsum += wy * h * q[n];
            iy += 0.5 * h * (oy + zy);
        }
        s5 += wy * iy;
    }
    (s5 / PI, qsum / PI)
}

/// Per point of a trace: (measured, lumped contact, lumped grid, local grid),
/// side force over the trace's μ_s; the local law has scale `t_local`.
fn trace(name: &str, t_local: f64) -> Vec<[f64; 4]> {
    let vi = DataTable::parse("appendix_vi_spin_traces.csv", APPENDIX_VI).unwrap();
    let col = |n: &str| vi.col(n).unwrap();
    let mut out = Vec::new();
    for i in (0..vi.rows.len()).filter(|&i| vi.str(i, col("trace")) == name) {
        let positive = vi.str(i, col("direction")) == "positive";
        let num = |n: &str| vi.num(i, col(n)).unwrap();
        let (m, mu, u, dv, mu_s) = (num("m"), num("mu"), num("U"), num("dV_U"), num("mu_spin"));
        let state = |law| {
            thermal::appendix_vi_state(name, positive, m, mu, u, dv, law)
                .unwrap()
                .0
        };
        // Inlet J groups from the contact without heating (T* = 1e12 K: the
        // law is 1 to 1e-19), the lumped prediction with the fluid's own law.
        let iso = state(Some(
            [Law {
                mu_coefficient: 0.0,
                mu_rise_scale: 1e12,
                slope_coefficient: 0.0,
                film: traction_contact::Film::FromFluid,
            }; 2],
        ));
        let th = state(None);
        let j = [iso.j1, iso.j2, iso.j3];
        let sign = iso.traction_y / (iso.mu_used * iso.j5);
        let to_meas = |j5: f64| sign * j5 * iso.mu_used / mu_s;
        let f_lumped = th.mu_used / iso.mu_used;
        let (j5_lumped, q_lumped) = grid(iso.k, j, Field::Uniform(f_lumped));
        // The law through the lumped solution: ln f = −(ΔT² − ΔT_peak²)/T*².
        let t_star = if name == "79100403" { 575.0 } else { 480.0 };
        let peak_sq = th.temperature_rise.powi(2) + t_star * t_star * f_lumped.ln();
        let law = move |dt: f64| (-(dt * dt - peak_sq) / (t_local * t_local)).exp();
        let h = th.temperature_rise / q_lumped;
        let (j5_local, _) = grid(iso.k, j, Field::Local { h, law: &law });
        out.push([
            num("FyFz_exp") / mu_s,
            th.traction_y / mu_s,
            to_meas(j5_lumped),
            to_meas(j5_local),
        ]);
    }
    out
}

fn rms(rows: &[[f64; 4]], col: usize) -> f64 {
    (rows.iter().map(|r| (r[col] - r[0]).powi(2)).sum::<f64>() / rows.len() as f64).sqrt()
}

/// Trace 79072704 (Santotrac 50, 80 m/s, 30° spin): the lumped rise fits it
/// (RMS 0.044), a local field does not, at the identified T* or any lower
/// one: at zero side slip spin alone gives a side force of −0.154 μ_s
/// (measured), −0.21 lumped, −0.35 … −0.37 local (isothermal −0.35): hot
/// spots where spin slides fastest lower the limit where the stress is
/// already plastic, while the region near the spin pole, which carries the
/// spin's side force, stays cool. Checked first: with a uniform factor the
/// grid is the contact's lumped prediction to 0.006 (the grid's first-order
/// error, 0.005 at N = 160 against the strip integrator).
#[test]
fn a_local_temperature_field_misses_the_high_spin_trace_that_the_lumped_rise_fits() {
    for t_local in [480.0, 380.0] {
        let rows = trace("79072704", t_local);
        let worst_grid = rows.iter().map(|r| (r[2] - r[1]).abs()).fold(0.0, f64::max);
        assert!(worst_grid < 0.006, "grid vs contact {worst_grid}");
        let (lumped, local) = (rms(&rows, 1), rms(&rows, 3));
        let zero = rows[0];
        println!("T* {t_local}: RMS lumped {lumped:.4} local {local:.4}; zero side slip {zero:?}");
        assert!(lumped < 0.05, "{lumped}");
        assert!(local > 2.0 * lumped, "{local} vs {lumped}");
        assert!(zero[3] < -0.33 && zero[1] > -0.22, "{zero:?}");
    }
}

/// Trace 79100403 (TDF-88, 80 m/s): the local field makes the fit worse
/// too, and does not steepen the rise below ΔV/U = 0.8 % that the
/// isothermal model misses (local/lumped at 0.39 % and 1.29 % ≈ 0.99 and
/// 0.97: a few per cent where 15–25 % are missing).
#[test]
fn a_local_temperature_field_does_not_steepen_the_rise_under_spin() {
    let rows = trace("79100403", 575.0);
    let (lumped, local) = (rms(&rows, 1), rms(&rows, 3));
    println!("79100403: RMS lumped {lumped:.4} local {local:.4}");
    assert!(local > lumped, "{local} vs {lumped}");
    for r in rows.iter().filter(|r| r[0] > 0.4 && r[0] < 0.8) {
        // measured / local: still ≥ 1.15 where the rise is missed.
        assert!(r[0] / r[3] > 1.15, "{r:?}");
    }
}
