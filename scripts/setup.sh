#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# setup.sh [--deb] -- install the build and test dependencies on Debian 12 (idempotent).
# --deb: also the Debian packaging tools (scripts/deb-package.sh, scripts/deb-chroot-test.sh).
# Installs only what is missing, with apt-get (non-interactive); runs `apt-get update`
# only when something has to be installed. Needs root (or sudo) only in that case.
set -euo pipefail

packages=(cmake gcc gfortran make pkg-config libpng-dev zlib1g-dev libcmocka-dev
          python3 groff-base man-db # reference pages: generator and their ctest (docs/man)
          libx11-dev xvfb xdotool x11-apps x11-utils # X11 workstation and its tests (optional)
          libopenmpi-dev openmpi-bin # OpenMPI: the optional MPI build and its test (docs/MPI.md)
          libcairo2-dev poppler-utils librsvg2-bin ghostscript # cairo: the PDF/SVG/PS/EPS
          # workstations; their tests open the files in pdftoppm, rsvg-convert and gs
          fonts-dejavu-core # the font of STRING and CHAR precision text in vector output
          libncarg-dev libncarg-bin ncl-ncarg libbz2-dev) # NCAR Graphics (optional): its
          # examples on the NCAR profile vs NCAR's own GKS and ctrans (tests/ncarg,
          # docs/NCAR.md); NCAR's ncargf77 links -lbz2, which no package here brings
if [ "${1:-}" = --deb ]; then
    packages+=(debhelper dpkg-dev fakeroot lintian mmdebstrap)
fi
missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all dependencies present (${packages[*]})"
    exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=()
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root to install ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
