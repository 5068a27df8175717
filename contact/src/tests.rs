//! Unit tests (exact solutions and invariants); the report reproductions live
//! in `tests/tests/contact_*.rs`.

use super::*;
use proptest::prelude::*;
use std::f64::consts::PI;
use std::sync::Arc;
use traction_rheology::Inputs;
use traction_rheology::closed;

/// Low-speed machine, k = 1 discs of Table 2-1.
fn ls_k1() -> (Body, Body) {
    (
        Body::steel(25e-3, 12.5e-3),
        Body::steel(25e-3, f64::INFINITY),
    )
}

/// High-speed machine, k = 5 discs of Table 2-1 (a contact with k ≠ 1).
fn hs_k5() -> (Body, Body) {
    (
        Body::steel(33e-3, 270e-3),
        Body::steel(71.4e-3, f64::INFINITY),
    )
}

fn contact(bodies: (Body, Body), fluid: Fluid, options: Options) -> TractionContact {
    TractionContact::new(&bodies.0, &bodies.1, fluid, options).expect("valid contact")
}

fn state(n: f64, u: f64, du: f64, dv: f64, w: f64) -> OperatingState {
    OperatingState::new(n, u, du, dv, w, 70.0).expect("valid state")
}

#[test]
fn zero_spin_matches_the_closed_form_exactly() {
    // Independent: Hertz k and a from traction-hertz, then App. V eq. 23 by hand.
    let c = contact(
        hs_k5(),
        Fluid::constant(52.4, 0.089).unwrap(),
        Options::default(),
    );
    let (n, u, du, dv) = (1500.0, 20.0, 0.03, -0.02);
    let r = c.evaluate(&state(n, u, du, dv, 0.0)).unwrap();
    let k = c.geometry().k;
    let cst = 3.0 * PI / 8.0 * (52.4 / 0.089) * k.sqrt();
    let (j1, j2) = (cst * du / u, cst * dv / u);
    let (j4, j5) = closed::combined_slip_traction(k, j1, j2);
    // Same closed form, evaluated through the contact: round-off only (1e-12).
    assert!((r.fx / (0.089 * n * j4) - 1.0).abs() < 1e-12);
    assert!((r.fy / (0.089 * n * j5) - 1.0).abs() < 1e-12);
    // The side force's aligning moment (closed::combined_slip_torque), 1e-12.
    let ab = c.geometry().at_load(n).map(|h| (h.a * h.b).sqrt()).unwrap();
    let j6 = closed::combined_slip_torque(k, j1, j2);
    assert!((r.mz / (0.089 * n * ab * j6) - 1.0).abs() < 1e-12);
    assert_eq!(r.regime, Regime::ElasticWithoutSpin);
    // Small-slip limit: Fx/N → m ΔU/U (the definition of m), 1e-4 relative at ΔU/U = 1e-7.
    let r = c.evaluate(&state(n, u, 2e-6, 0.0, 0.0)).unwrap();
    assert!((r.traction_x / (52.4 * 1e-7) - 1.0).abs() < 1e-4);
}

#[test]
fn power_balance_app_iv_eq_17() {
    // J7 = (3π/8)√k m/(μ² N U) (Fx ΔU + Fy ΔV + Mz ω): ties the J6 normalisation
    // Mz = μN√(ab)J6 to J3 = c ω√(ab)/U; round-off only (1e-10 relative).
    let c = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options::default(),
    );
    for (u, du, dv, w) in [
        (80.0, 0.1, 0.2, 17.0),
        (-30.0, -0.05, 0.1, -9.0),
        (5.0, 0.0, 0.0, 3.0),
    ] {
        let r = c.evaluate(&state(5000.0, u, du, dv, w)).unwrap();
        let j7 = 3.0 * PI / 8.0 * r.k.sqrt() * 35.0 / (0.075 * 0.075 * 5000.0 * u.abs()) * r.loss;
        assert!((r.j7 / j7 - 1.0).abs() < 1e-10, "{} vs {j7}", r.j7);
        assert!(r.loss > 0.0);
    }
}

#[test]
fn reversal_is_the_180_degree_frame_rotation() {
    // F(−U, −ΔU, −ΔV, ω) = (−Fx, −Fy, Mz) of F(U, ΔU, ΔV, ω): exact (1e-12), |U| ≥ U_f.
    let c = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options::default(),
    );
    for (u, du, dv, w) in [
        (20.0, 0.02, 0.05, 15.0),
        (3.0, -0.01, 0.002, -4.0),
        (1e-3, 1e-5, 0.0, 0.3),
    ] {
        let p = c.evaluate(&state(2000.0, u, du, dv, w)).unwrap();
        let m = c.evaluate(&state(2000.0, -u, -du, -dv, w)).unwrap();
        let tol = 1e-12 * 0.075 * 2000.0;
        assert!((p.fx + m.fx).abs() < tol && (p.fy + m.fy).abs() < tol);
        assert!((p.mz - m.mz).abs() < tol * 1e-3);
        assert_eq!((p.j1, p.j2, p.j3), (m.j1, m.j2, m.j3));
    }
}

#[test]
fn odd_symmetry_in_all_relative_motions() {
    // (ΔU, ΔV, ω) → −(ΔU, ΔV, ω) at the same U: forces and moment change sign
    // (the rheology's odd symmetry); the integrator is symmetric: 1e-12.
    let c = contact(
        ls_k1(),
        Fluid::constant(53.5, 0.083).unwrap(),
        Options::default(),
    );
    let p = c.evaluate(&state(3000.0, 20.0, 0.01, 0.03, 8.0)).unwrap();
    let m = c
        .evaluate(&state(3000.0, 20.0, -0.01, -0.03, -8.0))
        .unwrap();
    let tol = 1e-12 * 0.083 * 3000.0;
    assert!((p.fx + m.fx).abs() < tol && (p.fy + m.fy).abs() < tol);
    assert!((p.mz + m.mz).abs() < tol);
}

#[test]
fn zero_relative_motion_gives_zero_force_at_any_rolling_speed() {
    let c = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options::default(),
    );
    for u in [-50.0, -1e-3, -1e-6, 0.0, 1e-9, 2e-4, 80.0] {
        let r = c.evaluate(&state(1000.0, u, 0.0, 0.0, 0.0)).unwrap();
        assert_eq!((r.fx, r.fy, r.mz, r.loss), (0.0, 0.0, 0.0, 0.0), "U = {u}");
    }
}

#[test]
fn rolling_speed_through_zero_is_continuous() {
    // Slip, side slip and spin together; forces sampled across U = 0. The blend
    // is C¹ and the J's are Lipschitz in U (slope ~ J/U_f): a step of 1e-9 U_f
    // moves the forces by ~1e-9·μN·J, far below 1e-6 μN.
    let c = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options::default(),
    );
    let uf = DEFAULT_ROLLING_SPEED_FLOOR;
    let n = 1000.0;
    for &u0 in &[0.0, uf, -uf, 0.5 * uf] {
        let a = c
            .evaluate(&state(n, u0 - 1e-12, 2e-6, -1e-6, 0.02))
            .unwrap();
        let b = c
            .evaluate(&state(n, u0 + 1e-12, 2e-6, -1e-6, 0.02))
            .unwrap();
        let tol = 1e-6 * 0.075 * n;
        assert!(
            (a.fx - b.fx).abs() < tol,
            "Fx jumps at U = {u0}: {} {}",
            a.fx,
            b.fx
        );
        assert!((a.fy - b.fy).abs() < tol, "Fy jumps at U = {u0}");
        assert!((a.mz - b.mz).abs() < tol * 1e-3, "Mz jumps at U = {u0}");
    }
    // Without the blend the two rolling frames disagree at U = 0 (J3 changes
    // sign with the inlet side): the blend is doing real work.
    let k = c.geometry().k;
    let r = c.evaluate(&state(n, 0.0, 2e-6, -1e-6, 0.02)).unwrap();
    let cst = 3.0 * PI / 8.0 * (35.0 / 0.075) * k.sqrt();
    let j = [
        cst * 2e-6 / uf,
        cst * -1e-6 / uf,
        cst * 0.02 * (r.a * r.b).sqrt() / uf,
    ];
    let f = traction_rheology::evaluate(
        &Inputs::new(k, j[0], j[1], j[2]).unwrap(),
        Model::ElasticPlastic,
        Accuracy::default(),
    )
    .unwrap();
    let g = traction_rheology::evaluate(
        &Inputs::new(k, -j[0], -j[1], j[2]).unwrap(),
        Model::ElasticPlastic,
        Accuracy::default(),
    )
    .unwrap();
    assert!(
        (f.j5 + g.j5).abs() > 0.01,
        "branches agree: {} {}",
        f.j5,
        -g.j5
    );
    // At U = 0 the result is their mean (w = 1/2): 1e-12.
    assert!((r.fy / (0.075 * n) - 0.5 * (f.j5 - g.j5)).abs() < 1e-12);
}

#[test]
fn start_up_passes_to_the_rigid_plastic_limit() {
    // U → 0 with finite slip: J's ~ cΔ/U_f ≫ 1, forces → Coulomb μN along the slip.
    let c = contact(
        ls_k1(),
        Fluid::constant(57.6, 0.0956).unwrap(),
        Options::default(),
    );
    let n = 416.0;
    let r = c.evaluate(&state(n, 0.0, 0.5, 0.0, 0.0)).unwrap();
    // Closed form at J1 = c·0.5/1e-3 ≈ 8e5: 1 − ψ ≈ 8/(3πS) < 1e-5 (App. V eq. 22).
    assert!((r.traction_x / 0.0956 - 1.0).abs() < 1e-5);
    assert_eq!(r.regime, Regime::ElasticWithoutSpin);
    // Slip plus spin at a stop: the rigid/plastic solution of the rheology
    // crate at the same J ratios (elastic lag < 1e-3 at J ~ 1e5; tol 2e-3).
    let r = c.evaluate(&state(n, 0.0, 0.05, 0.02, 40.0)).unwrap();
    let inp = Inputs::new(r.k, r.j1, r.j2, r.j3).unwrap();
    let rp = traction_rheology::evaluate(&inp, Model::RigidPlastic, Accuracy::default()).unwrap();
    assert!(
        (r.j4 - rp.j4).abs() < 2e-3 && (r.j5 - rp.j5).abs() < 2e-3,
        "{r:?} {rp:?}"
    );
    assert_eq!(r.regime, Regime::RigidPlastic);
}

#[test]
fn open_and_vanishing_load() {
    let c = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options::default(),
    );
    let r = c.evaluate(&state(0.0, 20.0, 0.1, 0.1, 10.0)).unwrap();
    assert_eq!(
        (r.fx, r.fy, r.mz, r.loss, r.a, r.p0),
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    );
    let mut prev = f64::INFINITY;
    for n in [1e-3, 1e-12, 1e-30, 1e-300] {
        let r = c.evaluate(&state(n, 20.0, 0.1, 0.1, 10.0)).unwrap();
        for v in [
            r.fx, r.fy, r.mz, r.loss, r.j1, r.j2, r.j3, r.j4, r.j5, r.j6, r.j7,
        ] {
            assert!(v.is_finite());
        }
        assert!(r.fx.abs() <= 0.075 * n * (1.0 + 1e-9) && r.fx.abs() < prev);
        prev = r.fx.abs();
    }
    // Physical fluid: μ = τ̄πab/N grows like N^(-1/3) but the forces vanish.
    let c = contact(
        hs_k5(),
        Fluid::physical(1e9, 30e6, 0.3e-6).unwrap(),
        Options::default(),
    );
    let r = c.evaluate(&state(0.0, 20.0, 0.1, 0.0, 0.0)).unwrap();
    assert_eq!((r.fx, r.mu_used), (0.0, 0.0));
    let r = c.evaluate(&state(1e-20, 20.0, 0.1, 0.0, 0.0)).unwrap();
    assert!(r.fx.is_finite() && r.fx.abs() < 1e-9);
}

#[test]
fn physical_properties_are_app_iv_eq_10() {
    // Choose Ḡ, τ̄, h from (m, μ) at one load by eq. 10, by hand; the physical
    // fluid must then give the constant fluid's forces at that load (1e-12).
    let bodies = hs_k5();
    let (m, mu, n, h) = (35.0, 0.075, 5000.0, 0.4e-6);
    let hz = traction_hertz::solve_load(&bodies.0, &bodies.1, n).unwrap();
    let g = 3.0 / 8.0 * m * n * h / (hz.a * hz.a * hz.b);
    let tau = mu * n / (PI * hz.a * hz.b);
    let cp = contact(
        bodies,
        Fluid::physical(g, tau, h).unwrap(),
        Options::default(),
    );
    let cc = contact(bodies, Fluid::constant(m, mu).unwrap(), Options::default());
    let s = state(n, 80.0, 0.1, 0.05, 17.0);
    let (p, q) = (cp.evaluate(&s).unwrap(), cc.evaluate(&s).unwrap());
    assert!((p.m_used / m - 1.0).abs() < 1e-12 && (p.mu_used / mu - 1.0).abs() < 1e-12);
    assert!((p.fx / q.fx - 1.0).abs() < 1e-9 && (p.mz / q.mz - 1.0).abs() < 1e-9);
    // J1 = Ḡ√(ab)ΔU/(τ̄hU) (App. IV eq. 11 in physical form): 1e-12.
    let j1 = g * (hz.a * hz.b).sqrt() * 0.1 / (tau * h * 80.0);
    assert!((p.j1 / j1 - 1.0).abs() < 1e-12);
}

#[test]
fn compliance_series_and_conversion() {
    let bodies = ls_k1();
    let steel = DiscMaterial::REPORT_STEEL;
    let opts = |d| Options {
        compliance: Compliance::Discs {
            material: steel,
            slope_measured_in: d,
        },
        ..Options::default()
    };
    // Constant fluid measured in side slip: m_y = m, m_x from B7 (compliance crate).
    let c = contact(
        bodies,
        Fluid::constant(57.6, 0.0956).unwrap(),
        opts(Direction::Side),
    );
    let r = c.evaluate(&state(416.0, 20.0, 0.01, 0.0, 0.0)).unwrap();
    let mx = traction_compliance::convert_slope_same_contact(
        57.6,
        r.k,
        r.p0,
        Direction::Side,
        Direction::Longitudinal,
        steel,
    )
    .unwrap();
    assert_eq!(r.m_side, 57.6);
    assert!((r.m_used / mx - 1.0).abs() < 1e-12);
    // k = 1: Kalker C11 > C22 (q_x < q_y), the discs are stiffer along x, so m_x > m_y.
    assert!(r.m_used > r.m_side);
    // Physical fluid: film and discs in series, 1/m = 1/m_film + 2 q P0/(3 G_s), by hand.
    let c = contact(
        bodies,
        Fluid::physical(1e9, 30e6, 0.3e-6).unwrap(),
        opts(Direction::Side),
    );
    let off = contact(
        bodies,
        Fluid::physical(1e9, 30e6, 0.3e-6).unwrap(),
        Options::default(),
    );
    let s = state(416.0, 20.0, 0.01, 0.0, 0.0);
    let (r, r0) = (c.evaluate(&s).unwrap(), off.evaluate(&s).unwrap());
    let gs = steel.shear_modulus().unwrap();
    let qx = traction_compliance::kalker_q(Direction::Longitudinal, r.k, 0.3).unwrap();
    let m_series = 1.0 / (1.0 / r0.m_used + 2.0 * qx * r.p0 / (3.0 * gs));
    assert!((r.m_used / m_series - 1.0).abs() < 1e-12);
    assert!(r.m_used < r0.m_used);
}

#[test]
fn compliance_gives_the_rheology_its_stiffness_ratio() {
    // Compliance on, slip + side slip + spin on the k = 5 discs: the J's are
    // formed with m_x (J2 too) and the rheology gets gy = m_y/m_x; the
    // result must be the rheology called directly with those inputs (1e-12:
    // same code path, same accuracy) and obey the dimensional power balance
    // J7 = (3π/8)√k·m_x·P/(μ²NU) (1e-9).
    let opts = Options {
        compliance: Compliance::Discs {
            material: DiscMaterial::REPORT_STEEL,
            slope_measured_in: Direction::Side,
        },
        classify_regime: false,
        ..Options::default()
    };
    let c = contact(hs_k5(), Fluid::constant(35.0, 0.075).unwrap(), opts);
    let (n, u, du, dv, w) = (1500.0, 20.0, 0.02, 0.05, 40.0);
    let r = c.evaluate(&state(n, u, du, dv, w)).unwrap();
    let gy = r.m_side / r.m_used;
    assert!(
        (gy - 1.0).abs() > 0.01,
        "gy {gy}: the check would be vacuous"
    );
    let cx = 3.0 * PI / 8.0 * (r.m_used / r.mu_used) * r.k.sqrt();
    assert!((r.j2 / (cx * dv / u) - 1.0).abs() < 1e-12);
    assert!((r.j3 / (cx * w * (r.a * r.b).sqrt() / u) - 1.0).abs() < 1e-12);
    let inp = Inputs::new(r.k, r.j1, r.j2, r.j3)
        .unwrap()
        .with_stiffness_ratio(gy)
        .unwrap();
    let o = traction_rheology::evaluate(&inp, Model::ElasticPlastic, Accuracy::default()).unwrap();
    assert!((o.j4 - r.j4).abs() < 1e-12 && (o.j5 - r.j5).abs() < 1e-12);
    assert!((o.j6 - r.j6).abs() < 1e-12);
    let p = r.fx * du + r.fy * dv + r.mz * w;
    let j7 = cx * p / (r.mu_used * n * u);
    assert!((r.j7 / j7 - 1.0).abs() < 1e-9, "{} {j7}", r.j7);
    // The isotropic approximation differs (not a vacuous option).
    let iso = traction_rheology::evaluate(
        &Inputs::new(r.k, r.j1, r.j2, r.j3).unwrap(),
        Model::ElasticPlastic,
        Accuracy::default(),
    )
    .unwrap();
    assert!((iso.j5 - r.j5).abs() > 1e-3, "{} {}", iso.j5, r.j5);
}

#[test]
fn interpolation_map_option() {
    // Options::map: the same contact with the rheology's interpolation map
    // instead of direct integration. Forces within the accuracy: |ΔJ4..6| ≤
    // tol = 1e-3 (the map's own contract, rheology/tests/map.rs) against the
    // direct result at 1e-5; a slip sweep at spin (60 states) repeated 40
    // times builds its cells within the map's budget (≈ 1300 node
    // evaluations at 0.5 per call) and then reuses them (the last pass ≥
    // 80 % interpolated); the regime classification uses the
    // map's rigid/plastic solution and agrees; with compliance (gy ≠ 1) the
    // elastic/plastic map is not used and the forces are bit-identical to
    // the direct ones; a clone carries the map.
    let acc = Accuracy::new(1e-3).unwrap();
    let fluid = Fluid::constant(35.0, 0.075).unwrap();
    let mapped = contact(
        hs_k5(),
        fluid.clone(),
        Options {
            accuracy: acc,
            map: true,
            ..Options::default()
        },
    );
    let direct = contact(
        hs_k5(),
        fluid.clone(),
        Options {
            accuracy: Accuracy::new(1e-5).unwrap(),
            ..Options::default()
        },
    );
    assert!(mapped.map_stats().is_none());
    // Spin 40 and 400 rad/s: J3 ≈ 2 and 21 (the report's high-spin traces).
    let states: Vec<_> = (0..60)
        .map(|n| {
            let du = 0.002 * (n % 30) as f64 - 0.03;
            let w = if n < 30 { 40.0 } else { 400.0 };
            state(1500.0, 20.0, du, 0.01, w)
        })
        .collect();
    let references: Vec<_> = states
        .iter()
        .map(|st| direct.evaluate(st).unwrap())
        .collect();
    let mut last = MapStats::default();
    for pass in 0..40 {
        last = mapped.map_stats().unwrap_or_default();
        for (st, d) in states.iter().zip(&references) {
            let m = mapped.evaluate(st).unwrap();
            for (x, y) in [(m.j4, d.j4), (m.j5, d.j5), (m.j6, d.j6)] {
                assert!((x - y).abs() <= 1e-3, "pass {pass} {st:?}: {x} vs {y}");
            }
            assert!((m.fx - d.fx).abs() <= 1e-3 * d.mu_force * 1500.0);
            assert_eq!(m.regime, d.regime, "{st:?}");
            assert!(m.loss >= 0.0 && m.j7 >= 0.0);
        }
    }
    let s = mapped.map_stats().unwrap();
    assert!(s.interpolated - last.interpolated >= 48, "{s:?}");
    let copy = mapped.clone();
    assert_eq!(copy.map_stats(), mapped.map_stats());
    let st = state(1500.0, 20.0, 0.011, 0.01, 40.0);
    assert_eq!(copy.evaluate(&st).unwrap(), mapped.evaluate(&st).unwrap());
    // The map moves to a rebuilt contact with the same k and accuracy
    // (another load or fluid), not to one with another accuracy.
    let built = mapped.map_stats().unwrap();
    let m = mapped.take_map().unwrap();
    assert!(mapped.map_stats().is_none());
    let rebuilt = contact(
        hs_k5(),
        Fluid::constant(50.0, 0.09).unwrap(),
        Options {
            accuracy: acc,
            map: true,
            ..Options::default()
        },
    );
    assert!(rebuilt.adopt_map(m.clone()));
    assert_eq!(rebuilt.map_stats(), Some(built));
    assert!(!direct.adopt_map(m));
    // Compliance on: gy = m_y/m_x ≠ 1, the map does not apply.
    let compliant = |map| Options {
        accuracy: acc,
        compliance: Compliance::Discs {
            material: DiscMaterial::REPORT_STEEL,
            slope_measured_in: Direction::Side,
        },
        map,
        ..Options::default()
    };
    let (c1, c0) = (
        contact(hs_k5(), fluid.clone(), compliant(true)),
        contact(hs_k5(), fluid, compliant(false)),
    );
    let (e1, e0) = (c1.evaluate(&st).unwrap(), c0.evaluate(&st).unwrap());
    assert_eq!((e1.fx, e1.fy, e1.mz, e1.j4), (e0.fx, e0.fy, e0.mz, e0.j4));
    // Only the regime classification used the (rigid/plastic) map.
    let s1 = c1.map_stats().unwrap_or_default();
    assert_eq!(s1.interpolated + s1.direct, 0, "{s1:?}");
    assert_eq!(e1.regime, e0.regime);
}

/// The k ≈ 5 contact of `interpolation_map_option` with the map at tol.
fn mapped_k5(tol: f64) -> TractionContact {
    contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options {
            accuracy: Accuracy::new(tol).unwrap(),
            map: true,
            ..Options::default()
        },
    )
}

/// ΔU, ΔV (m/s) and ω (rad/s) of the state at load 1500 N, U = 20 m/s with
/// the given J1, J2, J3 on `c` (the J groups are linear in them there).
fn state_at_j(c: &TractionContact, j: [f64; 3]) -> OperatingState {
    let unit = c.evaluate(&state(1500.0, 20.0, 1e-3, 1e-3, 1.0)).unwrap();
    state(
        1500.0,
        20.0,
        j[0] * 1e-3 / unit.j1,
        j[1] * 1e-3 / unit.j2,
        j[2] / unit.j3,
    )
}

/// Node evaluations and cell checks the map spent, and the calls that
/// could earn credit (looked up a cell), elastic/plastic and rigid/plastic
/// together.
fn spent_and_calls(s: &MapStats) -> (u64, u64) {
    (
        s.nodes_computed + s.cells_checked,
        s.interpolated + s.direct + s.rigid_interpolated + s.rigid_direct,
    )
}

#[test]
fn interpolation_map_budget() {
    // The map's budget (traction-rheology Budget::DEFAULT): every call earns
    // 0.5 node evaluations, building a cell spends its new nodes and check.
    // Scattered states with spin (|J1|, |J2| ≤ 5, J3 in [5, 26], random):
    // the map spends at most 0.5 node evaluations per call (nodes cost
    // 1.4–7 direct evaluations, so ≤ 4.5 direct evaluations per call in
    // all) — counted, not timed — where the map without budget spends more
    // than 8 per call on the same J's; every value within tol = 1e-3 of
    // the direct one at 1e-5 (the map's contract, interpolated or direct).
    // A dense sequence (slip oscillating in a small region) still builds
    // its cells and ends up interpolated. The same sequence twice gives
    // bit-identical results, and so does a clone taken mid-way (the credit
    // is part of the cache).
    let tol = 1e-3;
    let reference = contact(
        hs_k5(),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options {
            accuracy: Accuracy::new(1e-5).unwrap(),
            ..Options::default()
        },
    );
    let mapped = mapped_k5(tol);
    let mut rng = traction_testkit::XorShift64::new(0x5eed_0078);
    let scattered: Vec<OperatingState> = (0..60)
        .map(|_| {
            let j = [
                10.0 * rng.unit() - 5.0,
                10.0 * rng.unit() - 5.0,
                5.0 + 21.0 * rng.unit(),
            ];
            state_at_j(&reference, j)
        })
        .collect();
    let mut js = Vec::new();
    for st in &scattered {
        let (m, d) = (
            mapped.evaluate(st).unwrap(),
            reference.evaluate(st).unwrap(),
        );
        for (x, y) in [(m.j4, d.j4), (m.j5, d.j5), (m.j6, d.j6)] {
            assert!((x - y).abs() <= tol, "{st:?}: {x} vs {y}");
        }
        js.push(Inputs::new(m.k, m.j1, m.j2, m.j3).unwrap());
    }
    let s = mapped.map_stats().unwrap();
    let (spent, calls) = spent_and_calls(&s);
    assert!(calls >= 60 && 2 * spent <= calls, "{s:?}");
    // The same J's through a map without budget.
    let mut unbounded =
        Map::new(mapped.geometry().k, 0.0, 1.0, Accuracy::new(tol).unwrap()).unwrap();
    for inp in &js {
        unbounded.evaluate(inp).unwrap();
    }
    let u = unbounded.stats();
    assert!(u.nodes_computed + u.cells_checked > 8 * 60, "{u:?}");
    // Dense: ΔU/U oscillating within ±0.02 % at J2 ≈ 0.5, J3 ≈ 10.
    let centre = state_at_j(&reference, [0.5, 0.5, 10.0]);
    let dense: Vec<OperatingState> = (0..1200)
        .map(|i| OperatingState {
            slip: centre.slip * (1.0 + 0.1 * (f64::from(i) * 0.05).sin()),
            ..centre
        })
        .collect();
    let fresh = mapped_k5(tol);
    let mut clone = None;
    let mut results = Vec::new();
    for (i, st) in dense.iter().enumerate() {
        if i == 600 {
            clone = Some(fresh.clone());
        }
        results.push(fresh.evaluate(st).unwrap());
    }
    let s = fresh.map_stats().unwrap();
    let (spent, calls) = spent_and_calls(&s);
    assert!(2 * spent <= calls && s.cells_checked > 0, "{s:?}");
    // Built within the first half, interpolated from then on.
    let mid = clone.as_ref().and_then(TractionContact::map_stats).unwrap();
    assert_eq!(s.interpolated - mid.interpolated, 600, "{mid:?} {s:?}");
    for (st, m) in dense.iter().zip(&results).step_by(50) {
        let d = reference.evaluate(st).unwrap();
        for (x, y) in [(m.j4, d.j4), (m.j5, d.j5), (m.j6, d.j6)] {
            assert!((x - y).abs() <= tol, "{st:?}: {x} vs {y}");
        }
    }
    // Same sequence, same results (bit for bit), from the start and from
    // the clone's history on.
    let again = mapped_k5(tol);
    for (st, r) in dense.iter().zip(&results) {
        assert_eq!(&again.evaluate(st).unwrap(), r);
    }
    assert_eq!(again.map_stats(), fresh.map_stats());
    let clone = clone.unwrap();
    for (st, r) in dense.iter().zip(&results).skip(600) {
        assert_eq!(&clone.evaluate(st).unwrap(), r);
    }
}

#[test]
fn property_distribution_option() {
    // G ∝ pressure, limit constant: the contact passes the option to the
    // rheology's grid scheme (same J's, same call: 1e-12) and it matters.
    let props = Properties {
        modulus: Modulus::PressureProportional,
        limit: Limit::Constant,
    };
    let opts = Options {
        properties: props,
        classify_regime: false,
        accuracy: Accuracy::new(1e-3).unwrap(),
        ..Options::default()
    };
    let fluid = || Fluid::constant(52.4, 0.089).unwrap();
    let c = contact(hs_k5(), fluid(), opts);
    let d = contact(
        hs_k5(),
        fluid(),
        Options {
            properties: Properties::default(),
            ..opts
        },
    );
    let s = state(1500.0, 20.0, 0.03, -0.02, 30.0);
    let (r, r0) = (c.evaluate(&s).unwrap(), d.evaluate(&s).unwrap());
    let inp = Inputs::new(r.k, r.j1, r.j2, r.j3).unwrap();
    let o =
        traction_rheology::evaluate(&inp, Model::PropertyVariation(props), opts.accuracy).unwrap();
    assert!((o.j4 - r.j4).abs() < 1e-12 && (o.j5 - r.j5).abs() < 1e-12);
    assert!((r.j4 - r0.j4).abs() > 1e-2, "{} {}", r.j4, r0.j4);
}

#[test]
fn kinematics_input_twin_disc() {
    // Tilted upper disc of the low-speed k = 1 rig (Table 2-4: e = R_y = 12.5 mm,
    // 6°): the general 3-D kinematics must give ω/U of eq. 6 (1e-12 relative).
    use traction_kinematics::{BodyMotion, contact_kinematics, tilted_disc_spin_per_speed};
    type V = nalgebra::Vector3<f64>;
    let (alpha, ry, e, r2) = (6f64.to_radians(), 12.5e-3, 12.5e-3, 25e-3);
    let rr = ry * alpha.cos() + e; // rolling radius of the tilted disc
    let u = 20.0;
    // Lower disc: axis along y through (0, 0, −r2), rolling along +x at the contact.
    let lower = BodyMotion::rotating(V::new(0.0, u / r2, 0.0), V::new(0.0, 0.0, -r2));
    // Upper disc: axis (0, cos α, −sin α) through the point rr/cos α above the
    // contact (distance rr from the contact), turning so its surface moves along +x.
    let axis = V::new(0.0, alpha.cos(), -alpha.sin());
    let centre = V::new(0.0, 0.0, rr / alpha.cos());
    let w1 = u / rr;
    let upper = BodyMotion::rotating(-axis * w1, centre);
    let kin = contact_kinematics(
        &upper,
        &lower,
        V::zeros(),
        V::new(0.0, 0.0, 1.0),
        V::new(1.0, 0.0, 0.0),
    )
    .unwrap();
    let s = OperatingState::from_kinematics(&kin, 416.0, 70.0).unwrap();
    let expect = tilted_disc_spin_per_speed(alpha, ry, e).unwrap();
    assert!(
        (s.spin / s.rolling_speed / expect - 1.0).abs() < 1e-9,
        "{} vs {expect}",
        s.spin / s.rolling_speed
    );
    assert!(s.slip.abs() < 1e-12 && s.side_slip.abs() < 1e-12);
    let c = contact(
        ls_k1(),
        Fluid::constant(53.5, 0.083).unwrap(),
        Options::default(),
    );
    let r = c.evaluate(&s).unwrap();
    assert!(r.j3 > 0.0 && r.fy.abs() > 0.0 && r.loss > 0.0);
}

#[test]
fn regimes_by_the_5_percent_criterion() {
    let c = contact(
        ls_k1(),
        Fluid::constant(53.5, 0.083).unwrap(),
        Options::default(),
    );
    let n = 416.0;
    // Region I: no spin.
    assert_eq!(
        c.evaluate(&state(n, 20.0, 0.02, 0.0, 0.0)).unwrap().regime,
        Regime::ElasticWithoutSpin
    );
    // Region III: spin J3 ~ 700 with traction ~ 0.75 (ε = J1/J3 near the speed pole).
    let r = c.evaluate(&state(n, 0.05, 0.02, 0.0, 50.0)).unwrap();
    assert!(r.j3 > 100.0, "{r:?}");
    assert_eq!(r.regime, Regime::RigidPlastic, "{r:?}");
    // Region II: J3 ≈ 2, J1 ≈ 2 (App. IV fig. 9: spin visibly lowers the traction).
    let cst = 3.0 * PI / 8.0 * 53.5 / 0.083;
    let hz = c.geometry().at_load(n).unwrap();
    let w = 2.0 / cst * 20.0 / (hz.a * hz.b).sqrt();
    let r = c
        .evaluate(&state(n, 20.0, 2.0 / cst * 20.0, 0.0, w))
        .unwrap();
    assert!((r.j3 - 2.0).abs() < 1e-9);
    assert_eq!(r.regime, Regime::ElasticWithSpin, "{r:?}");
    let no = Options {
        classify_regime: false,
        ..Options::default()
    };
    let c = contact(ls_k1(), Fluid::constant(53.5, 0.083).unwrap(), no);
    assert_eq!(
        c.evaluate(&state(n, 20.0, 0.02, 0.0, 5.0)).unwrap().regime,
        Regime::NotClassified
    );
}

#[test]
fn inverse_psi_inverts_psi() {
    // Independent check through the rheology crate's ψ: 1e-12.
    // Also tiny S (a bisection from [0, π/2] cannot reach it in 60 halvings)
    // and a sweep across the switch of the starting point at T = 1/2.
    let sweep = (0..200).map(|i| 10f64.powf(-3.0 + 0.025 * f64::from(i)));
    for s in [1e-200, 1e-6, 0.01, 0.5, 1.0, 3.0, 50.0, 1e3]
        .into_iter()
        .chain(sweep)
    {
        let t = closed::psi(s);
        // Conditioning: dS/S = dψ·π(1+S²)²/(4S²·S)·S ≈ (π/4)S³·ε for S ≫ 1.
        let tol = 1e-12 + 10.0 * PI / 4.0 * s.powi(3) * f64::EPSILON;
        assert!((inverse_psi(t) / s - 1.0).abs() < tol, "S = {s}");
    }
    assert_eq!(inverse_psi(0.0), 0.0);
    assert_eq!(inverse_psi(1.0), f64::INFINITY);
}

#[test]
fn errors_name_the_quantity() {
    let msg = |e: ContactError| error_chain(&e);
    assert!(
        msg(OperatingState::new(-1.0, 1.0, 0.0, 0.0, 0.0, 20.0).unwrap_err()).contains("load N")
    );
    assert!(
        msg(OperatingState::new(1.0, f64::NAN, 0.0, 0.0, 0.0, 20.0).unwrap_err())
            .contains("rolling speed U")
    );
    assert!(
        msg(OperatingState::new(1.0, 1.0, 0.0, 0.0, f64::INFINITY, 20.0).unwrap_err())
            .contains("spin ω")
    );
    assert!(
        msg(OperatingState::new(1.0, 1.0, 0.0, 0.0, 0.0, -300.0).unwrap_err())
            .contains("inlet temperature")
    );
    assert!(msg(Fluid::constant(0.0, 0.1).unwrap_err()).contains("traction slope m"));
    assert!(
        msg(Fluid::constant(30.0, f64::NAN).unwrap_err()).contains("peak traction coefficient μ")
    );
    assert!(msg(Fluid::physical(1e9, 3e7, -1.0).unwrap_err()).contains("film thickness h"));
    let bad = Body::steel(0.0, 1.0);
    let e = TractionContact::new(
        &bad,
        &Body::steel(1.0, 1.0),
        Fluid::constant(30.0, 0.1).unwrap(),
        Options::default(),
    );
    assert!(msg(e.unwrap_err()).starts_with("Hertz contact: "));
    // A contact too elongated for the traction model.
    let long = Body::steel(1.0, 1e-4);
    let e = TractionContact::new(
        &long,
        &Body::steel(1.0, f64::INFINITY),
        Fluid::constant(30.0, 0.1).unwrap(),
        Options::default(),
    );
    assert!(msg(e.unwrap_err()).contains("aspect ratio k"));
    let o = Options {
        rolling_speed_floor: 0.0,
        ..Options::default()
    };
    let e = TractionContact::new(
        &Body::steel(1.0, 1.0),
        &Body::steel(1.0, 1.0),
        Fluid::constant(30.0, 0.1).unwrap(),
        o,
    );
    assert!(msg(e.unwrap_err()).contains("rolling-speed floor"));
}

#[test]
fn a_non_finite_solver_output_is_an_error_naming_it() {
    use crate::contact::finite_outputs;
    assert_eq!(finite_outputs(&[("a", 1.0), ("b", -2.0)]), Ok(()));
    let e = finite_outputs(&[("a", 1.0), ("traction J4", f64::NAN), ("c", f64::INFINITY)]);
    let e = e.unwrap_err();
    assert!(
        matches!(
            e,
            ContactError::NonFinite {
                quantity: "traction J4",
                ..
            }
        ),
        "{e:?}"
    );
    assert!(error_chain(&e).contains("traction J4 = NaN is not finite"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every output finite; loss ≥ 0, J7 ≥ 0; the traction vector within the
    /// limit (|(J4, J5)| ≤ 1 + 1e-3, the rheology's default accuracy ×10).
    #[test]
    fn outputs_finite_and_dissipative(
        n in prop_oneof![Just(0.0), 1e-20f64..1e-3, 1.0f64..2e5],
        u in prop_oneof![Just(0.0), -1e-3f64..1e-3, -100.0f64..100.0],
        du in -5.0f64..5.0, dv in -5.0f64..5.0, w in prop_oneof![Just(0.0), -500.0f64..500.0],
        m in 5.0f64..200.0, mu in 0.01f64..0.2,
    ) {
        let c = contact(hs_k5(), Fluid::constant(m, mu).unwrap(), Options::default());
        let r = c.evaluate(&state(n, u, du * 1e-2, dv * 1e-2, w)).unwrap();
        for v in [r.fx, r.fy, r.mz, r.loss, r.traction_x, r.traction_y, r.a, r.b, r.p0,
                  r.j1, r.j2, r.j3, r.j4, r.j5, r.j6, r.j7, r.m_used, r.mu_used] {
            prop_assert!(v.is_finite());
        }
        prop_assert!(r.loss >= 0.0 && r.j7 >= 0.0);
        prop_assert!(r.j4.hypot(r.j5) <= 1.0 + 1e-3);
    }

    /// The 180° rotation about the normal (x → −x, y → −y) for |U| ≥ U_f: exact.
    #[test]
    fn frame_rotation_symmetry(
        u in 1e-3f64..80.0, du in -0.05f64..0.05, dv in -0.05f64..0.05, w in -50.0f64..50.0,
        n in 10.0f64..5000.0,
    ) {
        let c = contact(ls_k1(), Fluid::constant(53.5, 0.083).unwrap(), Options::default());
        let p = c.evaluate(&state(n, u, du, dv, w)).unwrap();
        let q = c.evaluate(&state(n, -u, -du, -dv, w)).unwrap();
        let tol = 1e-12 * 0.083 * n;
        prop_assert!((p.fx + q.fx).abs() <= tol && (p.fy + q.fy).abs() <= tol);
        prop_assert!((p.mz - q.mz).abs() <= tol);
    }

    /// Continuity in U across the floor band: forces at U and U + 1e-3 U_f
    /// differ by at most 1e-3·|J|·μN·(a few) (Lipschitz bound of the blend and J's).
    #[test]
    fn continuity_in_rolling_speed(
        t in -1.5f64..1.5, du in -1e-5f64..1e-5, w in -0.05f64..0.05,
    ) {
        let c = contact(hs_k5(), Fluid::constant(35.0, 0.075).unwrap(), Options::default());
        let uf = DEFAULT_ROLLING_SPEED_FLOOR;
        let n = 1000.0;
        let a = c.evaluate(&state(n, t * uf, du, 0.0, w)).unwrap();
        let b = c.evaluate(&state(n, (t + 1e-6) * uf, du, 0.0, w)).unwrap();
        let jmax = a.j1.abs().max(a.j3.abs()).max(1.0);
        let tol = 1e-6 * 10.0 * jmax * 0.075 * n;
        prop_assert!((a.fx - b.fx).abs() <= tol, "{} {}", a.fx, b.fx);
        prop_assert!((a.fy - b.fy).abs() <= tol, "{} {}", a.fy, b.fy);
    }
}

#[test]
fn report_fluid_through_the_correlations_and_envelope() {
    // Santotrac 50 inside its data (Table 2-3 class point: 1.45 GPa, 20 m/s,
    // 70 °C, k = 1): m and μ are the fluids crate's correlations at the Hertz P0
    // and k of the state (same function, composition check: 1e-12).
    let c = contact(
        ls_k1(),
        Fluid::santotrac_50(EnvelopeRule::Strict).unwrap(),
        Options::default(),
    );
    let hz = c.geometry().at_p0(1.45e9).unwrap();
    let r = c.evaluate(&state(hz.load, 20.0, 0.02, 0.0, 0.0)).unwrap();
    let f = traction_fluids::Fluid::santotrac_50().unwrap();
    let m = f.slope_m(r.p0, 20.0, 70.0, r.k).unwrap();
    let mu = f.mu(r.p0, 20.0, 70.0, r.k).unwrap();
    assert!((r.m_used / m - 1.0).abs() < 1e-12 && (r.mu_used / mu - 1.0).abs() < 1e-12);
    assert!(!r.outside_envelope.any());
    // Reversed rolling uses |U|: the same properties.
    let q = c.evaluate(&state(hz.load, -20.0, -0.02, 0.0, 0.0)).unwrap();
    assert_eq!((q.m_used, q.mu_used), (r.m_used, r.mu_used));
    // Start-up: U = 0 is outside the speed range of the data.
    let s0 = state(hz.load, 0.0, 0.02, 0.0, 0.0);
    let e = error_chain(&c.evaluate(&s0).unwrap_err());
    assert!(
        e.contains("rolling speed U") && e.contains("envelope"),
        "{e}"
    );
    // Clamp: properties at the envelope's lowest speed, flagged; forces finite.
    let cc = contact(
        ls_k1(),
        Fluid::santotrac_50(EnvelopeRule::Clamp).unwrap(),
        Options::default(),
    );
    let r0 = cc.evaluate(&s0).unwrap();
    let lo = f.slope.envelope.speed_m_s.0;
    let m_lo = f.slope_m(r0.p0, lo, 70.0, r0.k).unwrap();
    assert!((r0.m_used / m_lo - 1.0).abs() < 1e-12);
    assert!(r0.outside_envelope.speed && !r0.outside_envelope.p0 && r0.fx.is_finite());
    // Spin-peak correlation scales the forces when asked (TDF-88, refit III-F).
    let ct = contact(
        hs_k5(),
        Fluid::tdf_88(EnvelopeRule::Extrapolate)
            .unwrap()
            .use_spin_peak(true),
        Options::default(),
    );
    let hz = ct.geometry().at_p0(1.0e9).unwrap();
    let w = 0.0071 * 20.0 / (hz.a * hz.b).sqrt();
    let r = ct.evaluate(&state(hz.load, 20.0, 0.0, 0.05, w)).unwrap();
    assert!((r.traction_y - r.mu_force * r.j5).abs() < 1e-12);
    assert!(r.mu_force != r.mu_used);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Sign reversals at fixed U (either sign): (ΔU, ΔV, ω) → −(ΔU, ΔV, ω)
    /// reverses (Fx, Fy, Mz); the mirror y → −y, (ΔV, ω) → −(ΔV, ω), gives
    /// (Fx, −Fy, −Mz). Bound: twice the rheology's accuracy target (1e-4 in
    /// J4..J6) times μN (and μN√(ab) for Mz), in case the adaptive quadrature
    /// is not exactly symmetric.
    #[test]
    fn sign_symmetries(
        u in prop_oneof![-80.0f64..-1e-3, 1e-3f64..80.0],
        du in -0.05f64..0.05, dv in -0.05f64..0.05, w in -50.0f64..50.0,
    ) {
        let c = contact(hs_k5(), Fluid::constant(35.0, 0.075).unwrap(), Options::default());
        let n = 2000.0;
        let p = c.evaluate(&state(n, u, du, dv, w)).unwrap();
        let q = c.evaluate(&state(n, u, -du, -dv, -w)).unwrap();
        let r = c.evaluate(&state(n, u, du, -dv, -w)).unwrap();
        let tol = 2e-4 * 0.075 * n;
        let tolm = tol * (p.a * p.b).sqrt();
        prop_assert!((p.fx + q.fx).abs() <= tol && (p.fy + q.fy).abs() <= tol);
        prop_assert!((p.mz + q.mz).abs() <= tolm);
        prop_assert!((p.fx - r.fx).abs() <= tol && (p.fy + r.fy).abs() <= tol);
        prop_assert!((p.mz + r.mz).abs() <= tolm);
    }
}

#[test]
fn error_chain_prints_each_message_once() {
    // One error of each wrapping kind: the message names the context, the
    // cause is the source and appears once in the chain.
    let hertz = TractionContact::new(
        &Body::steel(0.0, 1.0),
        &Body::steel(1.0, 1.0),
        Fluid::constant(30.0, 0.1).unwrap(),
        Options::default(),
    )
    .unwrap_err();
    let c = TractionContact::new(
        &Body::steel(0.05, 0.05),
        &Body::steel(0.05, 0.05),
        Fluid::santotrac_50(EnvelopeRule::Strict).unwrap(),
        Options::default(),
    )
    .unwrap();
    let fluid = c
        .evaluate(&OperatingState::new(1000.0, 0.0, 0.02, 0.0, 0.0, 60.0).unwrap())
        .unwrap_err();
    for (e, context) in [(hertz, "Hertz contact"), (fluid, "fluid correlation")] {
        assert_eq!(e.to_string(), context);
        let cause = std::error::Error::source(&e).expect("a source").to_string();
        let text = error_chain(&e);
        assert_eq!(text, format!("{context}: {cause}"));
        assert_eq!(text.matches(cause.as_str()).count(), 1, "{text}");
    }
}

#[test]
fn report_fluids_are_built_once_and_shared() {
    // Every contact with a report fluid shares one set of correlations (the
    // compiled-in data are read once per process), with its own envelope.
    let arc = |f: &Fluid| match f {
        Fluid::Report { fluid, .. } => Some(Arc::clone(fluid)),
        _ => None,
    };
    for build in [Fluid::santotrac_50, Fluid::tdf_88] {
        let a = build(EnvelopeRule::Clamp).unwrap();
        let b = build(EnvelopeRule::Strict).unwrap();
        let (fa, fb) = (arc(&a).unwrap(), arc(&b).unwrap());
        assert!(Arc::ptr_eq(&fa, &fb));
        assert!(matches!(
            b,
            Fluid::Report {
                envelope: EnvelopeRule::Strict,
                ..
            }
        ));
    }
    let s = arc(&Fluid::santotrac_50(EnvelopeRule::Clamp).unwrap()).unwrap();
    let t = arc(&Fluid::tdf_88(EnvelopeRule::Clamp).unwrap()).unwrap();
    assert!(!Arc::ptr_eq(&s, &t));
    assert_ne!(s.name, t.name);
}
