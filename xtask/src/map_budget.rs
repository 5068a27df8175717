//! The cost of the contact's interpolation map against direct evaluation on a
//! scattered and on a dense sequence: `map-budget [N [TOL [NDENSE]]]`.
//!
//! * Scattered: N operating states of the k ≈ 5 high-speed contact whose J
//!   groups are random with |J1|, |J2| ≤ 5 and J3 in [5, 26], each evaluated
//!   once, with `Options::map` off (direct) and on.
//! * Dense: NDENSE states (default 10·N) of a slow slip sweep at fixed side slip and spin (one
//!   region of J space), map off and on.
//!
//! * Warm-up: the 64 states of the contact bench's `Options::map` case
//!   (trace 79072704, slip within ±1 %) cycled until a whole pass is
//!   interpolated; the number of evaluations that took.
//! * Rheology: N points (J1, J2 as above, k = 0.5, 1, 2, 5 in turn, one
//!   map per k) through `map::Map` without and with `Budget::DEFAULT` and
//!   directly (the sequence of docs/decisions/0043).
//!
//! Prints wall time (the machine's load is not controlled: record `uptime`),
//! the map's counters (deterministic) and the largest error of J4..J6 of
//! the map and of direct evaluation against direct evaluation at TOL/100
//! (on the scattered states; on every tenth dense state).
#![allow(clippy::unwrap_used)]
use crate::arg;
use std::time::Instant;
use traction_contact::{Accuracy, Body, Fluid, MapStats, OperatingState, Options, TractionContact};
use traction_rheology::map::{Budget, Map};
use traction_rheology::{Inputs, Model, evaluate};
use traction_testkit::XorShift64;

/// Load, rolling speed and inlet temperature of every state.
const LOAD: f64 = 1500.0;
const SPEED: f64 = 20.0;

fn contact(map: bool, tol: f64) -> TractionContact {
    TractionContact::new(
        &Body::steel(33e-3, 270e-3),
        &Body::steel(71.4e-3, f64::INFINITY),
        Fluid::constant(35.0, 0.075).unwrap(),
        Options {
            accuracy: Accuracy::new(tol).unwrap(),
            map,
            ..Options::default()
        },
    )
    .unwrap()
}

fn state(du: f64, dv: f64, w: f64) -> OperatingState {
    OperatingState::new(LOAD, SPEED, du, dv, w, 70.0).unwrap()
}

/// Runs the measurement with the command line's arguments after `map-budget`.
pub fn run(a: &[String]) -> Result<(), String> {
    let (n, tol): (usize, f64) = (arg(a, 0, "N", Some(2000))?, arg(a, 1, "TOL", Some(1e-3))?);
    let nd: usize = arg(a, 2, "NDENSE", Some(10 * n))?;
    // J1, J2, J3 are linear in ΔU, ΔV and ω at fixed load and speed.
    let probe = contact(false, tol);
    let unit = probe.evaluate(&state(1e-3, 1e-3, 1.0)).unwrap();
    let (per_du, per_dv, per_w) = (unit.j1 / 1e-3, unit.j2 / 1e-3, unit.j3);
    let mut xs = XorShift64::new(0x9e37_79b9_7f4a_7c15);
    let mut rnd = || xs.unit();
    let scattered: Vec<OperatingState> = (0..n)
        .map(|_| {
            let (j1, j2, j3) = (10.0 * rnd() - 5.0, 10.0 * rnd() - 5.0, 5.0 + 21.0 * rnd());
            state(j1 / per_du, j2 / per_dv, j3 / per_w)
        })
        .collect();
    // A slow slip sweep: J1 from −1 to 1 at J2 = 0.5, J3 = 10.
    let dense: Vec<OperatingState> = (0..nd)
        .map(|i| {
            let j1 = -1.0 + 2.0 * i as f64 / nd as f64;
            state(j1 / per_du, 0.5 / per_dv, 10.0 / per_w)
        })
        .collect();
    println!(
        "k = {:.3}, tol = {tol:.0e}, {n} scattered, {nd} dense states (J per unit: ΔU {per_du:.1}/(m/s), ΔV {per_dv:.1}/(m/s), ω {per_w:.4}/(rad/s))",
        probe.geometry().k
    );
    let reference = contact(false, tol / 100.0);
    for (name, states, every) in [("scattered", &scattered, 1), ("dense", &dense, 10)] {
        let n = states.len();
        // J4..J6 of every state and the time taken, in order.
        let timed = |c: &TractionContact| {
            let t0 = Instant::now();
            let j: Vec<[f64; 3]> = states
                .iter()
                .map(|s| {
                    let e = c.evaluate(s).unwrap();
                    [e.j4, e.j5, e.j6]
                })
                .collect();
            (j, t0.elapsed().as_secs_f64())
        };
        let (d, t_direct) = timed(&contact(false, tol));
        let mapped = contact(true, tol);
        let (m, t_map) = timed(&mapped);
        let (mut worst_map, mut worst_direct) = (0.0f64, 0.0f64);
        for i in (0..n).step_by(every) {
            let e = reference.evaluate(&states[i]).unwrap();
            for (c, r) in [e.j4, e.j5, e.j6].into_iter().enumerate() {
                if (m[i][c] - r).abs() > worst_map && std::env::var("V").is_ok() {
                    println!(
                        "  map error {:.2}·tol at J = ({:.4}, {:.4}, {:.4}), J{}",
                        (m[i][c] - r).abs() / tol,
                        e.j1,
                        e.j2,
                        e.j3,
                        c + 4
                    );
                }
                worst_map = worst_map.max((m[i][c] - r).abs());
                worst_direct = worst_direct.max((d[i][c] - r).abs());
            }
        }
        let s: MapStats = mapped.map_stats().unwrap_or_default();
        println!(
            "{name}: direct {:.3} s ({:.1} µs/state), map {:.3} s ({:.1} µs/state, {:.2}× direct); worst |ΔJ4..6| against tol/100: map {:.2}·tol, direct {:.2}·tol",
            t_direct,
            1e6 * t_direct / n as f64,
            t_map,
            1e6 * t_map / n as f64,
            t_map / t_direct,
            worst_map / tol,
            worst_direct / tol
        );
        println!("  map counters: {s:?}");
    }
    warm_up(tol);
    rheology(n, tol)
}

/// Evaluations until the contact bench's 64 warm states are all interpolated.
fn warm_up(tol: f64) {
    let c = contact(true, tol);
    let hz = c.geometry().at_load(5000.0).unwrap();
    let omega = 0.021 * 80.0 / (hz.a * hz.b).sqrt();
    let states: Vec<OperatingState> = (0..64)
        .map(|i| {
            let du = 0.4 * (1.0 + 0.01 * (f64::from(i) * 0.37).sin());
            OperatingState::new(5000.0, 80.0, du, 80.0 * 8.22e-3, omega, 73.0).unwrap()
        })
        .collect();
    for pass in 1..=400 {
        let before = c.map_stats().unwrap_or_default();
        for st in &states {
            c.evaluate(st).unwrap();
        }
        let s = c.map_stats().unwrap_or_default();
        if s.direct == before.direct && s.rigid_direct == before.rigid_direct {
            println!(
                "warm-up (contact bench states): all 64 interpolated in pass {pass}, after {} evaluations; {s:?}",
                64 * (pass - 1)
            );
            return;
        }
    }
    println!("warm-up (contact bench states): not warm after 400 passes");
}

const KS: [f64; 4] = [0.5, 1.0, 2.0, 5.0];

/// The rheology-level sequence: N points, k cycling through 0.5, 1, 2, 5.
fn rheology_points(n: usize) -> Vec<Inputs> {
    let mut xs = XorShift64::new(0x0043_0078_5eed_0001);
    let mut rnd = || xs.unit();
    (0..n)
        .map(|i| {
            let (j1, j2, j3) = (10.0 * rnd() - 5.0, 10.0 * rnd() - 5.0, 5.0 + 21.0 * rnd());
            Inputs::new(KS[i % 4], j1, j2, j3).unwrap()
        })
        .collect()
}

/// `map-budget-run direct|free|budget|dense-free|dense-budget N TOL`: only
/// the rheology-level sequence, one way, or a warm traction curve through a
/// map without or with budget (for callgrind: instruction counts do not
/// depend on the machine's load).
pub fn run_one(a: &[String]) -> Result<(), String> {
    let which = a.first().ok_or("direct|free|budget missing")?.clone();
    let (n, tol): (usize, f64) = (arg(a, 1, "N", Some(200))?, arg(a, 2, "TOL", Some(1e-3))?);
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let pts = rheology_points(n);
    if let Some(mode) = which.strip_prefix("dense-") {
        // N calls cycling over 64 points of a traction curve at k = 5
        // (warm after the first few thousand): the per-call cost of a warm
        // map is the difference of two runs with different N.
        let mut map = Map::new(5.0, 0.0, 1.0, acc).map_err(|e| e.to_string())?;
        if mode == "budget" {
            map = map.with_budget(Budget::DEFAULT);
        }
        for i in 0..n {
            let j1 = 0.5 + 0.01 * (i % 64) as f64;
            let inp = Inputs::new(5.0, j1, 0.3, 4.0).map_err(|e| e.to_string())?;
            std::hint::black_box(map.evaluate(&inp).map_err(|e| e.to_string())?);
        }
        return Ok(());
    }
    let budget = match which.as_str() {
        "direct" => {
            for p in &pts {
                evaluate(p, Model::ElasticPlastic, acc).map_err(|e| e.to_string())?;
            }
            return Ok(());
        }
        "free" => None,
        "budget" => Some(Budget::DEFAULT),
        other => return Err(format!("`{other}`: expected direct, free or budget")),
    };
    let mut maps = maps_of_ks(acc, budget);
    for (i, p) in pts.iter().enumerate() {
        maps[i % 4].evaluate(p).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// One empty map per aspect ratio of KS, with the given budget (none: a map
/// that builds every cell it needs).
fn maps_of_ks(acc: Accuracy, budget: Option<Budget>) -> Vec<Map> {
    KS.iter()
        .map(|&k| {
            let m = Map::new(k, 0.0, 1.0, acc).unwrap();
            match budget {
                Some(b) => m.with_budget(b),
                None => m,
            }
        })
        .collect()
}

/// The rheology-level sequence through maps without and with budget.
fn rheology(n: usize, tol: f64) -> Result<(), String> {
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let pts = rheology_points(n);
    let t0 = Instant::now();
    for p in &pts {
        evaluate(p, Model::ElasticPlastic, acc).unwrap();
    }
    let t_direct = t0.elapsed().as_secs_f64();
    for budget in [None, Some(Budget::DEFAULT)] {
        let mut maps = maps_of_ks(acc, budget);
        let t0 = Instant::now();
        for (i, p) in pts.iter().enumerate() {
            maps[i % 4].evaluate(p).unwrap();
        }
        let t_map = t0.elapsed().as_secs_f64();
        let (mut nodes, mut checks, mut interp) = (0, 0, 0);
        for m in &maps {
            let s = m.stats();
            nodes += s.nodes_computed;
            checks += s.cells_checked;
            interp += s.interpolated;
        }
        println!(
            "rheology, {}: direct {t_direct:.3} s, map {t_map:.3} s ({:.2}× direct); nodes {nodes}, checks {checks}, interpolated {interp} of {n}",
            if budget.is_some() {
                "budget"
            } else {
                "no budget"
            },
            t_map / t_direct
        );
    }
    Ok(())
}
