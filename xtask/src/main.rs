//! Developer tools of the traction workspace (`cargo xtask COMMAND ARGS`):
//!
//! - `prof CASE TOL REPS [GY]`: callgrind driver for the elastic/plastic benches;
//! - `prof-visco CASE TOL REPS [old|gauss]`: the same for the viscoelastic benches;
//! - `ir [ep|visco] [TOL [CASE...]]`: instructions per cold evaluation of the
//!   bench cases under callgrind, (Ir(3) − Ir(1))/2;
//! - `ep-batch FILE [N [TOL [REPS]]]`: per-row cost of a batch of
//!   elastic/plastic evaluations (CSV `k,J1,J2,J3`);
//! - `ep-sets refs|errs FILE [SEED]`, `ep-sets bits [TOL]`, `ep-sets lines
//!   [SEED [TOL [H]]]`, `ep-sets line K J1 J2 J3 D1 D2 D3 [TOL [N [H]]]`: the
//!   elastic/plastic solver against 128-panel references on 307 cases, its
//!   results' bits, and its smoothness along random lines or one line;
//! - `map-check K TOL N RLOG [DX GY]`: accuracy and hit rate of the rheology map on
//!   random points;
//! - `map-budget [N [TOL]]`: the contact's map against direct evaluation on a
//!   scattered and a dense sequence of operating states; `map-budget-run
//!   direct|free|budget|dense-free|dense-budget [N [TOL]]`: one way only,
//!   for callgrind.
//!
//! These are not user examples: they measure the implementation.
#![forbid(unsafe_code)]

mod ep_batch;
mod ep_sets;
mod ir;
mod map_budget;
mod map_check;
mod prof;
mod prof_visco;

const USAGE: &str = "usage: cargo xtask COMMAND ARGS
commands:
  prof [CASE [TOL [REPS [GY]]]]   callgrind driver: CASE m h p s a b c (bench set, prof.rs)
                                  or k,J1,J2,J3, TOL accuracy (default 1e-3), REPS
                                  evaluations (default 1), GY stiffness ratio gy (default 1);
                                  built with --features step-counts also the strips and
                                  plastic steps by kind per evaluation
  prof-visco [CASE [TOL [REPS [old|gauss]]]]
                                  the same for the viscoelastic model: CASE m h x l e g
                                  or k,J1,J2,J3,gy,D,Z0 (prof_visco.rs); `old` = the
                                  former fixed-grid scheme, `gauss` = the former
                                  Gauss-Legendre panel rule; with
                                  --features step-counts also its strips and steps
  ir [ep|visco] [TOL [CASE...]]   instructions per cold evaluation of the bench cases
                                  (default all, TOL 1e-3): prof/prof-visco under callgrind
                                  with 1 and 3 evaluations, (Ir(3) - Ir(1))/2 (ir.rs;
                                  needs valgrind)
  ep-batch FILE [N [TOL [REPS]]]  per-row wall time (fastest of REPS, default 3) of the
                                  first N rows (default 2000) of a CSV k,J1,J2,J3 at TOL
                                  (default 1e-4), one thread; summary by |J3|/sqrt(k), k
                                  and |Y_p| on stderr (ep_batch.rs)
  ep-sets refs FILE [SEED] | errs FILE [SEED] | bits [TOL] | lines [SEED [TOL [H]]]
        | line K J1 J2 J3 D1 D2 D3 [TOL [N [H]]]
                                  elastic/plastic solver on 307 cases (ep_sets.rs): write
                                  128-panel references, worst error/tol per set against
                                  them (SEED: other random cases), the results' bit
                                  patterns, the largest second differences along 180
                                  random lines (the worst line's start and direction in
                                  full; H: the same stretches at spacing H), or the
                                  second differences at each of N points (default 150)
                                  H (default 1e-4) apart along one line
  map-check K TOL N RLOG [DX GY]  rheology map against evaluate at TOL/100 on N random
                                  points, |J| log-uniform in [0.1, 10^(RLOG-1)]
  map-budget [N [TOL]]            the contact's map against direct evaluation: time and
                                  counters on N scattered and N dense states (default
                                  2000, TOL 1e-3)
  map-budget-run direct|free|budget|dense-free|dense-budget [N [TOL]]
                                  only the rheology-level scattered sequence, one way
                                  (direct, map without budget, map with Budget::DEFAULT),
                                  or N calls of a warm traction curve through a map
                                  without or with budget, for callgrind (default N 200,
                                  TOL 1e-3)";

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("ep-batch") => ep_batch::run(&args[1..]),
        Some("ep-sets") => ep_sets::run(&args[1..]),
        Some("ir") => ir::run(&args[1..]),
        Some("prof") => prof::run(&args[1..]),
        Some("prof-visco") => prof_visco::run(&args[1..]),
        Some("map-check") => map_check::run(&args[1..]),
        Some("map-budget") => map_budget::run(&args[1..]),
        Some("map-budget-run") => map_budget::run_one(&args[1..]),
        Some("help" | "-h" | "--help") => {
            println!("{USAGE}");
            Ok(())
        }
        Some(other) => Err(format!("unknown command `{other}`")),
        None => Err("no command given".to_string()),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}\n{USAGE}");
            std::process::ExitCode::from(2)
        }
    }
}

/// Parses argument `i` (named `name`) as `T`, or `default` when it is absent.
fn arg<T: std::str::FromStr>(
    a: &[String],
    i: usize,
    name: &str,
    default: Option<T>,
) -> Result<T, String> {
    match (a.get(i), default) {
        (Some(s), _) => s
            .parse()
            .map_err(|_| format!("{name}: cannot read `{s}` as a number")),
        (None, Some(d)) => Ok(d),
        (None, None) => Err(format!("{name} missing")),
    }
}
