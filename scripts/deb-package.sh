#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# deb-package.sh [OUT] -- build the Debian binary packages of this checkout (debian/) with
# `dpkg-buildpackage -us -uc -b` and check them with lintian, outside the work tree: the
# tracked files are copied into OUT/gks3d-VERSION (default OUT: /tmp/gks3d-deb, emptied
# first), the .deb files, .changes, build.log and lintian.txt end up in OUT. Exits non-zero
# if the build fails or lintian reports an error (E:). Installs the packaging tools first
# (scripts/setup.sh --deb). The build takes 65-96 s on 2 shared cores (the library, the
# bindings, the examples and the programs, -O2), 80 s-2 min with lintian.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/gks3d-deb}
scripts/setup.sh --deb
ver=$(dpkg-parsechangelog -S Version)
src=$out/gks3d-$ver
case $(cd "$(dirname "$out")" && pwd)/ in "$(pwd)"/*) echo "deb-package: OUT must be outside the work tree" >&2; exit 2 ;; esac
rm -rf "$out"
mkdir -p "$src"
git ls-files -z | tar --null -T - -cf - | tar -xf - -C "$src"
echo "deb-package: building gks3d $ver in $src (log: $out/build.log)"
start=$(date +%s)
if ! (cd "$src" && DEB_BUILD_OPTIONS="parallel=${JOBS:-2}" dpkg-buildpackage -us -uc -b) >"$out/build.log" 2>&1; then
    tail -40 "$out/build.log"
    echo "deb-package: dpkg-buildpackage failed" >&2
    exit 1
fi
echo "deb-package: built in $(( $(date +%s) - start )) s:"
ls -1 "$out"/*.deb
lintian --info "$out"/*.changes >"$out/lintian.txt" 2>&1 || true
echo "deb-package: lintian ($out/lintian.txt):"
grep -E '^[EWIP]: ' "$out/lintian.txt" || echo "(no tags)"
if grep -q '^E: ' "$out/lintian.txt"; then
    echo "deb-package: lintian reports errors" >&2
    exit 1
fi
