# Shared by scripts/*.sh (sourced, not run). Defines the repository root, the parallel job count and
# a configure helper. Environment knobs:
#   TESSERA_JOBS        parallel build/test jobs (default: number of cores)
#   TESSERA_SKIP_SETUP  set to 1 to skip the Debian package check (other distributions)
#   TESSERA_BUILD_DIR   build directory of demo.sh / test.sh (default: build)

TESSERA_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
JOBS=${TESSERA_JOBS:-$(nproc 2>/dev/null || echo 2)}

# step "message": a visible header for each stage of a script.
step() { printf '\n==> %s\n' "$*"; }

# setup: installs the Debian packages tessera needs unless they are all present.
setup() {
  if [[ ${TESSERA_SKIP_SETUP:-0} != 1 ]]; then
    "$TESSERA_ROOT/scripts/setup-debian.sh"
  fi
}

# configure DIR [cmake args...]: configures a Ninja build of the repository into DIR.
configure() {
  local dir=$1
  shift
  cmake -S "$TESSERA_ROOT" -B "$dir" -G Ninja -Wno-dev "$@"
}
