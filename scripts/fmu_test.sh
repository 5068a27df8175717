#!/usr/bin/env bash
# FMU importer tests: builds TractionContact.fmu (linux64 and win64) with
# `traction fmu build`, then checks it with real importers: fmpy validate, fmutool
# -check, FMPy simulate_fmu and FMU2Slave (drivetrain example), libcosimpy (two
# instances), ecospy `ecos simulate`; then runs the win64 DLL under Wine with a
# Windows FMI 2.0 master (fmu/tests/win/master.c, MinGW-w64) and compares every
# output with the same master on linux64 to 1e-12 of the output's scale; and the
# Rust examples examples/fmu_import.rs and variator_fmu_import.rs load the two FMUs with
# the `fmi` crate.
# Needs the tools of scripts/fmu_setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV="${FMU_VENV:-/tmp/fmuvenv}"
TARGET="${CARGO_TARGET_DIR:-target}"
mkdir -p "$TARGET/fmu"
OUT="$(realpath "$TARGET/fmu")"
FMU="$OUT/TractionContact.fmu"
cargo run --locked -q -p traction-cli -- fmu build --out "$FMU"
# The Rust example: the FMU loaded and stepped with the `fmi` crate.
cargo run --locked -q -p traction-examples --example fmu_import -- "$FMU"
TRACTION_FMU="$FMU" "$VENV/bin/python" -m pytest -q -p no:cacheprovider fmu/python
V="$OUT/ToroidalVariator.fmu"
cargo run --locked -q -p traction-cli -- fmu build --model variator --out "$V"
cargo run --locked -q -p traction-examples --example variator_fmu_import -- "$V"
TRACTION_VARIATOR_FMU="$V" "$VENV/bin/python" -m pytest -q -p no:cacheprovider variator-fmu/python

echo "== win64: TractionContact.dll under Wine against linux64"
start=$(date +%s)
WIN="$OUT/win"
rm -rf "$WIN" && mkdir -p "$WIN/win64" "$WIN/linux64"
# The binaries and the GUID from the archive itself.
python3 - "$FMU" "$WIN" <<'PY'
import re, sys, zipfile
fmu, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(fmu) as z:
    open(f"{out}/win64/TractionContact.dll", "wb").write(z.read("binaries/win64/TractionContact.dll"))
    open(f"{out}/linux64/TractionContact.so", "wb").write(z.read("binaries/linux64/TractionContact.so"))
    xml = z.read("modelDescription.xml").decode()
open(f"{out}/guid", "w").write(re.search(r'guid="([^"]+)"', xml).group(1))
PY
GUID="$(cat "$WIN/guid")"
x86_64-w64-mingw32-gcc -O1 -Wall -Wextra -Werror -o "$WIN/win64/master.exe" fmu/tests/win/master.c
# Test harness only: Rust's std imports ProcessPrng from bcryptprimitives.dll,
# which Wine 8 lacks; this stand-in forwards it to RtlGenRandom.
x86_64-w64-mingw32-gcc -O1 -Wall -Werror -shared -o "$WIN/win64/bcryptprimitives.dll" \
    fmu/tests/win/bcryptprimitives.c -ladvapi32
cc -O1 -Wall -Wextra -Werror -o "$WIN/linux64/master" fmu/tests/win/master.c -ldl
WINE="$(dpkg -L wine64 | grep -E '/wine64$' | head -n 1)"
export WINEPREFIX="$WIN/prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
(cd "$WIN/win64" && "$WINE" master.exe TractionContact.dll "$GUID" >../win64.txt 2>../win64.log) ||
    { cat "$WIN/win64.log"; exit 1; }
"$WIN/linux64/master" "$WIN/linux64/TractionContact.so" "$GUID" >"$WIN/linux64.txt" 2>"$WIN/linux64.log" ||
    { cat "$WIN/linux64.log"; exit 1; }
# Tolerance: 1e-12 relative to the output's largest magnitude over the scenario.
# The two binaries use different libm implementations (glibc; MinGW-w64/msvcrt)
# whose sin, cos, exp, pow differ in the last bit; an output that is itself a
# cancellation residue (fy ~ 1e-18 N at zero side slip) differs by more than
# 1e-12 of its own value, never of the output's scale.
python3 - "$WIN/linux64.txt" "$WIN/win64.txt" <<'PY'
import sys
def read(path):
    rows = {}
    for line in open(path):
        case, step, name, value = line.split()
        rows[(case, int(step), name)] = float(value)
    return rows
lin, win = read(sys.argv[1]), read(sys.argv[2])
assert lin.keys() == win.keys() and len(lin) > 1000, f"{len(lin)} vs {len(win)} values"
scale = {}
for (case, _, name), a in lin.items():
    scale[case, name] = max(scale.get((case, name), 0.0), abs(a))
worst, worst_own, bad, identical = 0.0, 0.0, [], 0
for key, a in lin.items():
    b = win[key]
    identical += a == b
    s = scale[key[0], key[2]]
    rel = 0.0 if a == b else abs(a - b) / s
    worst = max(worst, rel)
    if abs(a) >= 1e-9 * s:
        worst_own = max(worst_own, 0.0 if a == b else abs(a - b) / max(abs(a), abs(b)))
    if rel > 1e-12:
        bad.append((key, a, b))
print(f"win64 vs linux64: {len(lin)} values, {identical} bit-identical; max difference "
      f"{worst:.3g} of the output's scale, {worst_own:.3g} of the value itself "
      f"(values above 1e-9 of the scale)")
for key, a, b in bad[:10]:
    print(f"  {key}: linux64 {a!r}, win64 {b!r}")
print(f"{len(lin) - len(bad)} passed, {len(bad)} failed")
sys.exit(1 if bad else 0)
PY
echo "win64 test: $(($(date +%s) - start)) s"
