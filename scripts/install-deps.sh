#!/usr/bin/env bash
# Installs the Debian 12 packages glint builds against, skipping those already present.
# With --bench, also POV-Ray and Blender, the reference renderers of bench/spd_vs_povray,
# bench/distributed_vs_povray and bench/path_vs_cycles.
set -euo pipefail

packages=(
    build-essential cmake pkg-config clang-format git lld
    clang libclang-rt-14-dev
    libyaml-cpp-dev libtbb-dev libpng-dev libdeflate-dev zlib1g-dev libopenexr-dev libstb-dev
    libassimp-dev libembree-dev libpolyclipping-dev libfreetype-dev
    libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
    graphviz  # the tests render `glint explain --format dot` with it
    python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module and its tests
    jupyter-nbconvert python3-ipykernel python3-matplotlib  # the notebooks, run as tests
    povray-includes  # POV-Ray's standard include files, which .pov scenes #include
    libopenmpi-dev openmpi-bin  # glint-mpi, rendering across machines
    libcpp-httplib-dev  # glint-serve, the page in the browser
    chromium chromium-driver python3-selenium  # its tests, in a real browser
)
[ "${1:-}" = "--bench" ] && packages+=(povray blender)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages are present"
    exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
        echo "install-deps: error: not running as root and sudo is not installed;" \
            "run this script as root, or install these packages: ${missing[*]}" >&2
        exit 1
    fi
    sudo="sudo"
fi

echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
# Through env: sudo resets the environment, so a plain assignment would not reach apt-get.
$sudo env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
