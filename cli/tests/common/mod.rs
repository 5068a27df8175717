//! Shared support of the CLI integration tests: run the `traction` binary with
//! arguments and standard input, and collect its output.
#![allow(dead_code)] // each test file uses a subset

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Run `traction args...` with `stdin` piped in.
///
/// The command may exit (usage error) before reading stdin: a broken pipe is
/// then expected; any other write error fails the test.
pub fn traction(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_traction"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn traction");
    if let Err(e) = child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(stdin.as_bytes())
    {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().expect("wait for traction")
}

/// [`traction`], returning (success, stdout, stderr) as strings.
pub fn run(args: &[&str], stdin: &str) -> (bool, String, String) {
    let out = traction(args, stdin);
    (
        out.status.success(),
        String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        String::from_utf8(out.stderr).expect("stderr is UTF-8"),
    )
}

/// Run on stdin, expect success, return the output lines split into cells.
pub fn ok(args: &[&str], stdin: &str) -> Vec<Vec<String>> {
    let out = traction(args, stdin);
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .expect("stdout is UTF-8")
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// Run on stdin, expect failure with nothing on stdout; return stderr.
pub fn fails(args: &[&str], stdin: &str) -> String {
    let out = traction(args, stdin);
    assert!(!out.status.success());
    assert!(out.stdout.is_empty(), "partial output written");
    String::from_utf8(out.stderr).expect("stderr is UTF-8")
}
