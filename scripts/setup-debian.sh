#!/usr/bin/env bash
# Installs the Debian 12 packages tessera's build, tests, examples and benchmarks need, and only the
# missing ones: when everything is present it touches nothing (no apt-get update, no root needed).
# Uses sudo when not run as root.
set -euo pipefail

packages=(build-essential cmake ninja-build pkg-config ccache libeigen3-dev libglm-dev libnanoflann-dev
          catch2 libstb-dev libbenchmark-dev libopenmesh-dev)
# Optional: clang with libFuzzer for the fuzzers (scripts/fuzz.sh, the fuzz step of .ci/run) and
# clang-format 14 for the house-style check (structural: formatted as .clang-format says). Installed
# when missing, but a failure to install them only warns: everything else works without them.
optional=(clang libclang-rt-14-dev clang-format-14)
# CGAL for the mesh Booleans (geo-wang map --boolean; optional and GPL: TESSERA_WITH_CGAL)
optional+=(libcgal-dev)
# the Python module (python/, issue 20) and its Dask example; the module is skipped with a message without them
optional+=(pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-dev python3-pip python3-venv python3-setuptools
  python3-dask python3-distributed python3-zarr)

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "setup: not a Debian system (no dpkg-query); install the equivalents of: ${packages[*]}" >&2
  echo "setup: continuing; set TESSERA_SKIP_SETUP=1 to skip this check" >&2
  exit 0
fi

installed() { [[ $(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) == "install ok installed" ]]; }
missing=() missing_optional=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
for p in "${optional[@]}"; do installed "$p" || missing_optional+=("$p"); done
if ((${#missing[@]} == 0 && ${#missing_optional[@]} == 0)); then
  echo "setup: all ${#packages[@]} Debian packages and ${#optional[@]} optional ones are installed"
  exit 0
fi

echo "setup: installing ${missing[*]} ${missing_optional[*]}"
sudo=()
if ((EUID != 0)); then
  if ! command -v sudo >/dev/null 2>&1; then
    if ((${#missing[@]} == 0)); then
      echo "setup: optional packages (${missing_optional[*]}) missing and not root: no fuzzers, no format check" >&2
      exit 0
    fi
    echo "setup: missing packages (${missing[*]}) and not root; run as root or install sudo" >&2
    exit 1
  fi
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
if ((${#missing[@]} > 0)); then
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
if ((${#missing_optional[@]} > 0)); then
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing_optional[@]}" ||
    echo "setup: could not install the optional ${missing_optional[*]}: no fuzzers (scripts/fuzz.sh) or format check" >&2
fi
