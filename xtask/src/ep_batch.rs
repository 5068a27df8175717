//! Per-row cost of a batch of elastic/plastic evaluations:
//! `ep-batch FILE [N [TOL [REPS]]]` evaluates the first N rows (default
//! 2000) of a CSV with columns `k,J1,J2,J3` (by name; `traction jt`'s input) at
//! TOL (default 1e-4, `evaluate`'s default), one thread, and prints each
//! row's wall time in µs (the fastest of REPS evaluations, default 3) as
//! CSV on stdout; on stderr a summary: mean, percentiles, the share of the
//! rows that makes half the total, and the total's shares by |J3|/√k (the
//! spin relative to the contact's aspect ratio), by k and by |Y_p| (the spin
//! pole's strip, J1/(√k·J3)). Times depend on the machine's load: record
//! `uptime` with them; for ratios run it under callgrind (REPS 1).
#![allow(clippy::unwrap_used)]
use crate::arg;
use std::time::Instant;
use traction_rheology::{Accuracy, Inputs, Model, evaluate};
use traction_testkit::Table;

/// Runs the driver with the command line's arguments after `ep-batch`.
pub fn run(a: &[String]) -> Result<(), String> {
    let file = a.first().ok_or("FILE missing")?;
    let n: usize = arg(a, 1, "N", Some(2000))?;
    let tol: f64 = arg(a, 2, "TOL", Some(1e-4))?;
    let reps: usize = arg(a, 3, "REPS", Some(3))?;
    let text = std::fs::read_to_string(file).map_err(|e| format!("{file}: {e}"))?;
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let table = Table::parse(&text);
    // (k, J1, J2, J3, µs)
    let mut rows: Vec<[f64; 5]> = Vec::with_capacity(n);
    let cols = ["k", "J1", "J2", "J3"];
    if let Some(c) = cols.iter().find(|c| !table.header.iter().any(|h| h == *c)) {
        return Err(format!("{file}: no column `{c}` (needs k,J1,J2,J3)"));
    }
    println!("k,J1,J2,J3,us");
    for i in 0..table.rows.len().min(n) {
        let mut v = [0.0; 4];
        for (x, c) in v.iter_mut().zip(cols) {
            let cell = table.rows[i]
                .get(table.column(c))
                .map_or("", String::as_str);
            *x = cell
                .parse()
                .map_err(|_| format!("{file} row {}: `{cell}` in column {c}", i + 1))?;
        }
        let inp = Inputs::new(v[0], v[1], v[2], v[3]).map_err(|e| e.to_string())?;
        let mut best = f64::INFINITY;
        for _ in 0..reps.max(1) {
            let t0 = Instant::now();
            let o = evaluate(std::hint::black_box(&inp), Model::ElasticPlastic, acc);
            best = best.min(t0.elapsed().as_secs_f64() * 1e6);
            o.map_err(|e| e.to_string())?;
        }
        println!("{},{},{},{},{best:.2}", v[0], v[1], v[2], v[3]);
        rows.push([v[0], v[1], v[2], v[3], best]);
    }
    summary(&rows);
    Ok(())
}

/// The summary of the rows' times on stderr.
fn summary(rows: &[[f64; 5]]) {
    if rows.is_empty() {
        return;
    }
    let mut t: Vec<f64> = rows.iter().map(|r| r[4]).collect();
    t.sort_by(|a, b| b.total_cmp(a));
    let total: f64 = t.iter().sum();
    let pct = |q: f64| t[((1.0 - q) * (t.len() - 1) as f64).round() as usize];
    let mut acc = 0.0;
    let half = t.iter().take_while(|&&x| {
        acc += x;
        acc < 0.5 * total
    });
    let n_half = half.count() + 1;
    eprintln!(
        "{} rows: mean {:.1} µs, median {:.1}, p90 {:.1}, p99 {:.1}, max {:.1}; \
         {:.1} % of the rows make half the total",
        t.len(),
        total / t.len() as f64,
        pct(0.5),
        pct(0.9),
        pct(0.99),
        t[0],
        100.0 * n_half as f64 / t.len() as f64
    );
    let by = |name: &str, edges: &[f64], key: &dyn Fn(&[f64; 5]) -> f64| {
        eprintln!("{name}: bin, rows, mean µs, share of the total");
        for w in edges.windows(2) {
            let sel: Vec<f64> = rows
                .iter()
                .filter(|r| (w[0]..w[1]).contains(&key(r)))
                .map(|r| r[4])
                .collect();
            if !sel.is_empty() {
                let s: f64 = sel.iter().sum();
                eprintln!(
                    "  [{}, {}): {} {:.1} {:.3}",
                    w[0],
                    w[1],
                    sel.len(),
                    s / sel.len() as f64,
                    s / total
                );
            }
        }
    };
    let inf = f64::INFINITY;
    by(
        "|J3|/√k",
        &[0.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, inf],
        &|r| r[3].abs() / r[0].sqrt(),
    );
    by("k", &[0.0, 0.3, 0.5, 0.8, 1.3, 2.0, 3.2, inf], &|r| r[0]);
    by("|Y_p|", &[0.0, 0.25, 0.5, 0.75, 1.0, 2.0, inf], &|r| {
        (r[1] / (r[0].sqrt() * r[3])).abs()
    });
}
