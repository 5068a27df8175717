#!/usr/bin/env bash
# The README's test command: every test of the project.
#  1. installs the FMU importers if missing (scripts/fmu_setup.sh: Debian libclang-dev and
#     libtbb12, a Python venv with FMPy, fmutool, libcosimpy, ecospy);
#  2. cargo test: unit, golden (report tables), property, CLI and doc tests of every crate;
#  3. the examples of examples/ (each checks its own results);
#  4. the report reproduction: `traction reproduce` exits non-zero if any table leaves the
#     tolerance its golden test uses;
#  5. the FMU: build TractionContact.fmu and run it in the real importers and the Rust
#     example that loads it with the `fmi` crate.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== FMU test tools"
bash scripts/fmu_setup.sh

echo "== cargo test (workspace)"
cargo test --workspace --locked

echo "== examples (built by cargo test; run here)"
for example in hertz_contact traction_curve_with_spin contact_time_loop; do
    cargo run --locked -q -p traction-examples --example "$example"
done

echo "== report reproduction (traction reproduce; reuses the test build)"
cargo run --locked -q -p traction-cli -- reproduce --out target/reproduce --jobs 2

echo "== FMU: build TractionContact.fmu and run the importer tests"
bash scripts/fmu_test.sh
