//! Benchmarks of one full contact evaluation and of its parts.
//!
//! The case: high-speed machine, k = 5 discs (Table 2-1), trace 79072704 of
//! Appendix VI (m = 35, μ = 0.075, N = 5000 N, U = 80 m/s, Z = 0.021) with side
//! slip ΔV/U = 8.22e-3 and 0.5 % longitudinal slip — slip, side slip and spin
//! together. Parts: Hertz at the load, the rheology alone at the same J's, the
//! regime classification, and the zero-spin closed-form path.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_contact::{
    Accuracy, Body, EnvelopeRule, Fluid, Model, OperatingState, Options, Thermal, TractionContact,
};

fn bodies() -> (Body, Body) {
    (
        Body::steel(33e-3, 270e-3),
        Body::steel(71.4e-3, f64::INFINITY),
    )
}

fn contact(options: Options) -> TractionContact {
    let (b1, b2) = bodies();
    TractionContact::new(
        &b1,
        &b2,
        Fluid::constant(35.0, 0.075).expect("fluid"),
        options,
    )
    .expect("contact")
}

fn state(spin: f64) -> OperatingState {
    OperatingState::new(5000.0, 80.0, 0.4, 80.0 * 8.22e-3, spin, 73.0).expect("state")
}

fn bench(c: &mut Criterion) {
    let full = contact(Options::default());
    let hz = full.geometry().at_load(5000.0).expect("hertz");
    let omega = 0.021 * 80.0 / (hz.a * hz.b).sqrt();
    let s = state(omega);
    let r = full.evaluate(&s).expect("evaluation");
    eprintln!(
        "case: J1 = {:.3}, J2 = {:.3}, J3 = {:.3}; regime {:?}",
        r.j1, r.j2, r.j3, r.regime
    );

    c.bench_function("evaluate, spin, tol 1e-4, regime", |b| {
        b.iter(|| full.evaluate(black_box(&s)))
    });
    // The thermal contact: Santotrac 50 with the trace's m, μ at the inlet,
    // its own thermal properties; against the isothermal evaluation of the
    // same fluid (the cost ratio of the thermal model).
    let santotrac = |thermal| {
        let (b1, b2) = bodies();
        let f = Fluid::santotrac_50(EnvelopeRule::Clamp)
            .and_then(|f| f.with_inlet_values(35.0, 0.075))
            .expect("fluid");
        TractionContact::new(
            &b1,
            &b2,
            f,
            Options {
                thermal,
                ..Options::default()
            },
        )
        .expect("contact")
    };
    let iso = santotrac(None);
    let hot = santotrac(Some(Thermal::default()));
    let e = hot.evaluate(&s).expect("thermal");
    eprintln!(
        "thermal case: rise {:.1} K, μ {:.4}",
        e.temperature_rise, e.mu_used
    );
    c.bench_function(
        "thermal: isothermal reference, spin, tol 1e-4, regime",
        |b| b.iter(|| iso.evaluate(black_box(&s))),
    );
    c.bench_function("thermal: evaluate, spin, tol 1e-4, regime", |b| {
        b.iter(|| hot.evaluate(black_box(&s)))
    });
    // The same state without spin (closed forms).
    let s0 = state(0.0);
    c.bench_function("thermal: isothermal reference, zero spin, regime", |b| {
        b.iter(|| iso.evaluate(black_box(&s0)))
    });
    c.bench_function("thermal: evaluate, zero spin, regime", |b| {
        b.iter(|| hot.evaluate(black_box(&s0)))
    });
    let no_regime = contact(Options {
        classify_regime: false,
        ..Options::default()
    });
    c.bench_function("evaluate, spin, tol 1e-4, no regime", |b| {
        b.iter(|| no_regime.evaluate(black_box(&s)))
    });
    let coarse = contact(Options {
        classify_regime: false,
        accuracy: Accuracy::new(1e-3).expect("tol"),
        ..Options::default()
    });
    c.bench_function("evaluate, spin, tol 1e-3, no regime", |b| {
        b.iter(|| coarse.evaluate(black_box(&s)))
    });
    // Options::map: the interpolation map, warm (slip varied within ±1 % so
    // that the points differ but stay in built cells), with the regime.
    for tol in [1e-3, 1e-4] {
        let mapped = contact(Options {
            accuracy: Accuracy::new(tol).expect("tol"),
            map: true,
            ..Options::default()
        });
        let states: Vec<OperatingState> = (0..64)
            .map(|i| {
                let du = 0.4 * (1.0 + 0.01 * (f64::from(i) * 0.37).sin());
                OperatingState::new(5000.0, 80.0, du, 80.0 * 8.22e-3, omega, 73.0).expect("state")
            })
            .collect();
        for st in &states {
            mapped.evaluate(st).expect("evaluation");
        }
        let before = mapped.map_stats().unwrap_or_default();
        let mut n = 0usize;
        c.bench_function(
            &format!("evaluate, spin, map (warm), tol {tol:.0e}, regime"),
            |b| {
                b.iter(|| {
                    n = (n + 1) & 63;
                    mapped.evaluate(black_box(&states[n]))
                })
            },
        );
        let after = mapped.map_stats().unwrap_or_default();
        eprintln!(
            "map tol {tol:.0e}: interpolated {} direct {}, rigid interpolated {} direct {}",
            after.interpolated - before.interpolated,
            after.direct - before.direct,
            after.rigid_interpolated - before.rigid_interpolated,
            after.rigid_direct - before.rigid_direct
        );
    }
    // With the report fluid: Hertz + three correlations (m, μ, μ_s) + rheology.
    let (b1, b2) = bodies();
    let report = TractionContact::new(
        &b1,
        &b2,
        Fluid::santotrac_50(EnvelopeRule::Clamp)
            .expect("fluid")
            .use_spin_peak(true),
        Options::default(),
    )
    .expect("contact");
    c.bench_function("evaluate, spin, Santotrac 50 correlations, tol 1e-4", |b| {
        b.iter(|| report.evaluate(black_box(&s)))
    });
    let report0 = TractionContact::new(
        &b1,
        &b2,
        Fluid::santotrac_50(EnvelopeRule::Clamp)
            .expect("fluid")
            .use_spin_peak(true),
        Options {
            classify_regime: false,
            ..Options::default()
        },
    )
    .expect("contact");
    let s0 = state(0.0);
    c.bench_function("evaluate, no spin, Santotrac 50 correlations", |b| {
        b.iter(|| report0.evaluate(black_box(&s0)))
    });
    c.bench_function("evaluate, no spin (closed form)", |b| {
        b.iter(|| full.evaluate(black_box(&s0)))
    });
    // Parts.
    let geometry = *full.geometry();
    c.bench_function("part: Hertz at load", |b| {
        b.iter(|| geometry.at_load(black_box(5000.0)))
    });
    let inp = traction_rheology::Inputs::new(r.k, r.j1, r.j2, r.j3).expect("inputs");
    c.bench_function("part: rheology elastic/plastic, tol 1e-4", |b| {
        b.iter(|| {
            traction_rheology::evaluate(black_box(&inp), Model::ElasticPlastic, Accuracy::default())
        })
    });
    c.bench_function("part: rheology rigid/plastic (regime), tol 1e-4", |b| {
        b.iter(|| {
            traction_rheology::evaluate(black_box(&inp), Model::RigidPlastic, Accuracy::default())
        })
    });
    c.bench_function("build: TractionContact::new (Hertz geometry)", |b| {
        b.iter(|| {
            TractionContact::new(
                black_box(&b1),
                &b2,
                Fluid::Constant {
                    slope: 35.0,
                    peak: 0.075,
                    spin_peak: None,
                },
                Options::default(),
            )
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
