#!/usr/bin/env bash
# Installs hush's build and test dependencies from Debian 12 (bookworm) packages.
#
# Idempotent: it asks dpkg which packages are already installed and only runs
# apt-get (update + install) when something is missing, so a second run touches
# nothing. Runs unattended as root; elsewhere it uses sudo when that exists.
set -euo pipefail

# Every package hush needs, and nothing else. Why each one is here:
packages=(
  build-essential               # C/C++ compiler (C++20) and make
  cmake                         # >= 3.25 (bookworm ships 3.25)
  ninja-build                   # the generator the scripts use
  pkg-config
  git
  mesa-vulkan-drivers           # lavapipe: a Vulkan device without a GPU
  libvulkan-dev                 # Vulkan headers and loader
  libvulkan-volk-dev            # volk: loads Vulkan entry points at run time
  glslang-tools                 # glslangValidator: GLSL -> SPIR-V at build time
  spirv-cross                   # SPIRV-Cross tool
  libspirv-cross-c-shared-dev   # SPIRV-Cross libraries (core is used for reflection)
  libembree-dev                 # the CPU path tracer (tracer/)
  libopenexr-dev                # frame files (tracer/)
  libglm-dev                    # maths (tracer/)
  libimath-dev                  # half.h: fp16 conversion (core/)
  nlohmann-json3-dev            # JSON scene and chain files (tracer/, passes/)
  libpng-dev                    # PNG images of the denoised frames (samples/cli)
  libcairo2-dev                 # hush sweep's plots, SVG and PNG (samples/cli)
  libfontconfig-dev             # the plots' fonts: caches released at exit (samples/cli)
  libglfw3-dev                  # hush-viewer's window (samples/viewer; headless without it)
  catch2                        # test framework (v2)
  vulkan-validationlayers       # tests run with validation + synchronization validation
  vulkan-tools                  # vulkaninfo, for diagnosing a machine
  python3-torch                 # the RDAE training toolkit (samples/rdae_training) and its tests; not the C++ build
  python3-numpy
  python3-matplotlib            # the training's loss curve (PNG)
)

log() { printf '[setup] %s\n' "$*"; }

is_installed() {
  # "install ok installed" is dpkg's status for a fully configured package.
  [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

if ! command -v dpkg-query >/dev/null 2>&1; then
  log "error: dpkg-query not found; this script supports Debian 12 (bookworm) only." >&2
  exit 1
fi

if [[ -r /etc/os-release ]]; then
  # shellcheck disable=SC1091
  . /etc/os-release
  if [[ "${ID:-}" != "debian" || "${VERSION_ID:-}" != "12" ]]; then
    log "warning: expected Debian 12, found ${PRETTY_NAME:-unknown}; continuing anyway."
  fi
fi

missing=()
for pkg in "${packages[@]}"; do
  is_installed "$pkg" || missing+=("$pkg")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  log "all ${#packages[@]} packages already installed; nothing to do."
  exit 0
fi

# Root installs directly; anyone else needs sudo.
as_root=()
if [[ "$(id -u)" -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    log "error: missing packages (${missing[*]}) and not root, and sudo is not available." >&2
    log "run this script as root, or install them: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

export DEBIAN_FRONTEND=noninteractive
log "installing ${#missing[@]} missing package(s): ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"

# Verify rather than trust apt's exit code: a package held back would otherwise
# surface later as a confusing CMake error.
still_missing=()
for pkg in "${missing[@]}"; do
  is_installed "$pkg" || still_missing+=("$pkg")
done
if [[ ${#still_missing[@]} -ne 0 ]]; then
  log "error: still not installed after apt-get: ${still_missing[*]}" >&2
  exit 1
fi
log "done."
