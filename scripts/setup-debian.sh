#!/usr/bin/env bash
# Installs the Debian 12 packages tessera's build, tests, examples and benchmarks need, and only the
# missing ones: when everything is present it touches nothing (no apt-get update, no root needed).
# Uses sudo when not run as root.
set -euo pipefail

packages=(build-essential cmake ninja-build pkg-config ccache libeigen3-dev libglm-dev libnanoflann-dev
          catch2 libstb-dev libbenchmark-dev libopenmesh-dev)

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "setup: not a Debian system (no dpkg-query); install the equivalents of: ${packages[*]}" >&2
  echo "setup: continuing; set TESSERA_SKIP_SETUP=1 to skip this check" >&2
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  if [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) != "install ok installed" ]]; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} Debian packages are installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=()
if ((EUID != 0)); then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "setup: missing packages (${missing[*]}) and not root; run as root or install sudo" >&2
    exit 1
  fi
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
