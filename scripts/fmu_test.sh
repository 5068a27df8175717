#!/usr/bin/env bash
# FMU importer tests: builds TractionContact.fmu with `traction fmu build`, then
# checks it with real importers: fmpy validate, fmutool -check, FMPy simulate_fmu
# and FMU2Slave (drivetrain example), libcosimpy (two instances), ecospy `ecos simulate`,
# and the Rust example examples/fmu_import.rs (the `fmi` crate).
# Needs the tools of scripts/fmu_setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV="${FMU_VENV:-/tmp/fmuvenv}"
TARGET="${CARGO_TARGET_DIR:-target}"
mkdir -p "$TARGET/fmu"
FMU="$(realpath "$TARGET/fmu")/TractionContact.fmu"
cargo run --locked -q -p traction-cli -- fmu build --out "$FMU"
# The Rust example: the FMU loaded and stepped with the `fmi` crate.
cargo run --locked -q -p traction-examples --example fmu_import -- "$FMU"
TRACTION_FMU="$FMU" "$VENV/bin/python" -m pytest -q -p no:cacheprovider fmu/python
