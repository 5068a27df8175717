#!/usr/bin/env bash
# FMU importer tests: builds TractionContact.fmu with `traction fmu build`, then
# checks it with real importers: fmpy validate, fmutool -check, FMPy simulate_fmu
# and FMU2Slave (drivetrain example), libcosimpy (two instances), ecospy `ecos simulate`.
# Needs the tools of scripts/fmu_setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV="${FMU_VENV:-/tmp/fmuvenv}"
TARGET="${CARGO_TARGET_DIR:-target}"
mkdir -p "$TARGET/fmu"
FMU="$(realpath "$TARGET/fmu")/TractionContact.fmu"
cargo run --locked -q -p traction-cli -- fmu build --out "$FMU"
TRACTION_FMU="$FMU" "$VENV/bin/python" -m pytest -q -p no:cacheprovider fmu/python
V="$(realpath "$TARGET/fmu")/ToroidalVariator.fmu"; cargo run --locked -q -p traction-cli -- fmu build --model variator --out "$V" && TRACTION_VARIATOR_FMU="$V" "$VENV/bin/python" -m pytest -q -p no:cacheprovider variator-fmu/python
