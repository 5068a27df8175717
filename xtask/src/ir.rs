//! Instructions per cold evaluation of the bench cases, the figure the
//! decision records compare: `ir [ep|visco] [TOL [CASE...]]` runs this
//! program's `prof` (or `prof-visco`) driver under callgrind with 1 and with
//! 3 evaluations of each case and prints (Ir(3) − Ir(1))/2, which leaves out
//! the start-up and the first evaluation's one-time costs. Instruction
//! counts do not depend on the machine's load (unlike wall time), so they
//! compare builds on a shared machine; they are not wall time (a
//! cache-missing or dividing instruction costs more than an add). Needs
//! `valgrind` on the PATH (Debian: `apt-get install valgrind`).
use std::path::Path;
use std::process::Command;

use traction_testkit::bench_cases::{ELASTIC_PLASTIC, VISCOELASTIC};

/// Runs the command with the command line's arguments after `ir`.
pub fn run(a: &[String]) -> Result<(), String> {
    let model = a.first().map(String::as_str).unwrap_or("ep");
    let (driver, letters): (&str, Vec<&str>) = match model {
        "ep" => ("prof", ELASTIC_PLASTIC.iter().map(|c| c.letter).collect()),
        "visco" => (
            "prof-visco",
            VISCOELASTIC.iter().map(|c| c.letter).collect(),
        ),
        other => return Err(format!("unknown model `{other}` (ep, visco)")),
    };
    let tol = a.get(1).map(String::as_str).unwrap_or("1e-3");
    crate::arg::<f64>(a, 1, "TOL", Some(1e-3))?;
    let cases: Vec<&str> = if a.len() > 2 {
        a[2..].iter().map(String::as_str).collect()
    } else {
        letters.clone()
    };
    if let Some(c) = cases.iter().find(|c| !letters.contains(c)) {
        return Err(format!(
            "unknown case `{c}` of `{model}` ({})",
            letters.join(" ")
        ));
    }
    let exe = std::env::current_exe().map_err(|e| format!("cannot find this program: {e}"))?;
    for (i, c) in cases.iter().enumerate() {
        let one = collected(&exe, driver, c, tol, 1)?;
        let three = collected(&exe, driver, c, tol, 3)?;
        if i == 0 {
            println!("# instructions per evaluation, {model}, tol {tol}: (Ir(3) - Ir(1))/2");
        }
        println!("{c} {}", three.saturating_sub(one) / 2);
    }
    Ok(())
}

/// The instructions callgrind collected running `exe driver case tol reps`.
fn collected(exe: &Path, driver: &str, case: &str, tol: &str, reps: u32) -> Result<u64, String> {
    let out = Command::new("valgrind")
        .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
        .arg(exe)
        .args([driver, case, tol, &reps.to_string()])
        .output()
        .map_err(|e| {
            format!("cannot run valgrind ({e}); install it (Debian: apt-get install valgrind)")
        })?;
    let err = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        return Err(format!(
            "`{driver} {case} {tol} {reps}` under valgrind failed:\n{err}"
        ));
    }
    err.lines()
        .find_map(|l| {
            let (_, n) = l.split_once("Collected :")?;
            n.trim().parse().ok()
        })
        .ok_or_else(|| format!("no `Collected :` line in valgrind's output:\n{err}"))
}
