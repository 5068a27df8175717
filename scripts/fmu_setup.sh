#!/usr/bin/env bash
# Installs what the FMU tests need on a fresh Debian machine (run as root by .ci/run):
#  - Debian: libclang-dev (bindgen in the `fmi` crate's build, used by the Rust
#    importer test), libtbb12 (libcosimpy's native library);
#  - the win64 binary and its test: the Rust target x86_64-pc-windows-gnu, Debian
#    gcc-mingw-w64-x86-64 (its linker, and the compiler of the Windows test master)
#    and wine64 (runs that master; without recommends: no fonts, X or sound);
#  - PyPI, into a venv ($FMU_VENV, default /tmp/fmuvenv): FMPy, fmu-manipulation-toolbox
#    (fmutool), libcosimpy, ecospy, pytest. Versions pinned to the ones tested.
set -euo pipefail
VENV="${FMU_VENV:-/tmp/fmuvenv}"
need_apt=()
for pkg in libclang-dev libtbb12; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need_apt+=("$pkg")
done
need_win=()
for pkg in gcc-mingw-w64-x86-64 wine64; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need_win+=("$pkg")
done
if ((${#need_apt[@]} + ${#need_win[@]})); then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    if ((${#need_apt[@]})); then
        apt-get install -y -qq "${need_apt[@]}" >/dev/null
    fi
    if ((${#need_win[@]})); then
        apt-get install -y -qq --no-install-recommends "${need_win[@]}" >/dev/null
    fi
fi
if ! rustup target list --installed | grep -qx x86_64-pc-windows-gnu; then
    rustup target add x86_64-pc-windows-gnu
fi
if [[ ! -x "$VENV/bin/python" ]]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install -q --disable-pip-version-check \
    "fmpy==0.3.32" "fmu-manipulation-toolbox==2.0" "libcosimpy==0.0.6" "ecospy==0.7.2" "pytest"
# ecospy's wheel may ship its `ecos` binary without the execute bit.
chmod +x "$("$VENV/bin/python" -c 'import ecospy, os; print(os.path.join(os.path.dirname(ecospy.__file__), "binaries", "ecos"))')"
echo "FMU test tools ready in $VENV"
