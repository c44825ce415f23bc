#!/usr/bin/env bash
# Installs the Debian 12 packages glint builds against, skipping those already present.
# With --bench, also POV-Ray, the reference renderer of bench/spd_vs_povray.
set -euo pipefail

packages=(
    build-essential cmake pkg-config clang-format
    libyaml-cpp-dev libtbb-dev libpng-dev zlib1g-dev libopenexr-dev libstb-dev
    libassimp-dev libembree-dev
    libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
)
[ "${1:-}" = "--bench" ] && packages+=(povray)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages are present"
    exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
