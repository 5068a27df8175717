#!/usr/bin/env bash
# Installs what the FMU tests need on a fresh Debian machine (run as root by .ci/run):
#  - Debian: libclang-dev (bindgen in the `fmi` crate's build, used by the Rust
#    importer test), libtbb12 (libcosimpy's native library);
#  - PyPI, into a venv ($FMU_VENV, default /tmp/fmuvenv): FMPy, fmu-manipulation-toolbox
#    (fmutool), libcosimpy, ecospy, pytest. Versions pinned to the ones tested.
set -euo pipefail
VENV="${FMU_VENV:-/tmp/fmuvenv}"
need_apt=()
for pkg in libclang-dev libtbb12; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need_apt+=("$pkg")
done
if ((${#need_apt[@]})); then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq "${need_apt[@]}" >/dev/null
fi
if [[ ! -x "$VENV/bin/python" ]]; then
    python3 -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install -q --disable-pip-version-check \
    "fmpy==0.3.32" "fmu-manipulation-toolbox==2.0" "libcosimpy==0.0.6" "ecospy==0.7.2" "pytest"
# ecospy's wheel may ship its `ecos` binary without the execute bit.
chmod +x "$("$VENV/bin/python" -c 'import ecospy, os; print(os.path.join(os.path.dirname(ecospy.__file__), "binaries", "ecos"))')"
echo "FMU test tools ready in $VENV"
