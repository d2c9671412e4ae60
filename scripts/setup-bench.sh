#!/bin/sh
# SPDX-License-Identifier: MIT
# setup-bench.sh -- installs the peer renderers and gnuplot used by bench/compare and
# bench/speed_error, from Debian packages only (nothing built or installed by hand):
#   libembree-dev    Embree 3 (rtcIntersect1 / rtcOccluded1), headers + library
#   libgmp-dev       GMP: cmp_embree judge decides disagreements in exact rational arithmetic
#   tachyon-bin-nox  Tachyon (uniform-grid ray tracer reading NFF), command-line renderer
#   povray           POV-Ray 3.7
#   gnuplot-nox      plots of bench/speed_error (PNG via the pngcairo / png terminals)
#   libosmesa6-dev   Mesa llvmpipe through OSMesa, the peer of bench/raster/bench_gks
# Already installed packages are skipped; sudo is used only when not running as root.
set -eu

PKGS="libembree-dev libgmp-dev tachyon-bin-nox povray gnuplot-nox libosmesa6-dev"

missing=""
for p in $PKGS; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done

if [ -z "$missing" ]; then
    echo "setup-bench: all peers installed ($PKGS)"
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
else
    SUDO="sudo"
fi

echo "setup-bench: installing$missing"
$SUDO apt-get update
# shellcheck disable=SC2086 # word splitting of the package list is intended
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends $missing
echo "setup-bench: done"
