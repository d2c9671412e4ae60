#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# deb-chroot-test.sh [DEBDIR] [TARBALL] -- install the Debian packages built by
# scripts/deb-package.sh (DEBDIR, default /tmp/gks3d-deb) into a fresh Debian 12 (a chroot
# unpacked from TARBALL, a minbase bookworm tarball, default /var/tmp/fresh-bookworm.tar;
# made with mmdebstrap if it is absent), then, inside it, as a user of the packages does:
#   - apt-get install the .debs (all but -dbgsym) and gcc, gfortran, pkg-config;
#   - build tests/install/consumer_c/consumer.c with `pkg-config --cflags --libs gks3d` and
#     tests/install/consumer_f77/consumer.f with `pkg-config --cflags --libs gks3d-fortran`,
#     run both with no environment variable and check their PNG files and the version;
#   - check that the serial program maps no MPI library although libgks3d-mpi is installed,
#     and that nff_view --help runs.
# Needs root (chroot, mount). Not run by CI: it downloads about 150 packages (27-74 s here
# with a near mirror, 40 s-2 min with unpacking and removing the chroot; longer with a slow
# one). The chroot is removed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
debdir=${1:-/tmp/gks3d-deb}
tarball=${2:-/var/tmp/fresh-bookworm.tar}
[ "$(id -u)" = 0 ] || { echo "deb-chroot-test: needs root (chroot)" >&2; exit 1; }
ls "$debdir"/libgks3d0_*.deb >/dev/null || { echo "deb-chroot-test: no packages in $debdir (scripts/deb-package.sh)" >&2; exit 1; }
root=$(mktemp -d /var/tmp/gks3d-chroot.XXXXXX)
cleanup() {
    umount "$root/proc" 2>/dev/null || true
    rm -rf "$root"
}
trap cleanup EXIT
start=$(date +%s)
if [ -f "$tarball" ]; then
    tar -xf "$tarball" -C "$root"
else
    echo "deb-chroot-test: $tarball absent, making a minbase bookworm with mmdebstrap"
    mmdebstrap --variant=minbase bookworm "$root" >/dev/null
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mkdir -p "$root/tmp/debs" "$root/tmp/work"
for d in "$debdir"/*.deb; do
    case $d in *-dbgsym_*) ;; *) cp "$d" "$root/tmp/debs/" ;; esac
done
cp tests/install/consumer_c/consumer.c tests/install/consumer_f77/consumer.f "$root/tmp/work/"
cat >"$root/tmp/work/test.sh" <<'IN'
set -eu
export DEBIAN_FRONTEND=noninteractive
apt-get update -q >/tmp/work/apt.log
apt-get install -y -q --no-install-recommends /tmp/debs/*.deb gcc gfortran pkg-config libc6-dev \
    >>/tmp/work/apt.log
echo "installed: $(dpkg-query -W -f='${Package} ${Version}\n' 'libgks3d*' 'gks3d*' | tr '\n' ' ')"
cd /tmp/work
unset LD_LIBRARY_PATH
echo "pkg-config --cflags --libs gks3d: $(pkg-config --cflags --libs gks3d)"
cc -std=c11 -o consumer consumer.c $(pkg-config --cflags --libs gks3d)
./consumer c.png
echo "pkg-config --cflags --libs gks3d-fortran: $(pkg-config --cflags --libs gks3d-fortran)"
gfortran -o consumer_f77 consumer.f $(pkg-config --cflags --libs gks3d-fortran)
./consumer_f77 | tee f77.out
v=$(awk '$1 == "GKSVER" { print $2 "." $3 "." $4 }' f77.out)
[ "$v" = "$(pkg-config --modversion gks3d)" ] || { echo "GKSVER gives $v"; exit 1; }
od -A n -t x1 -N 8 gks7.png | grep -q '89 50 4e 47 0d 0a 1a 0a' || { echo "gks7.png is not a PNG"; exit 1; }
echo "Fortran consumer: gks7.png written, version $v"
# MPI only under a launcher: the module is installed, the serial programs map no MPI.
ls /usr/lib/*/gks3d/libgks3d-mpi.so
if ldd ./consumer ./consumer_f77 | grep -i mpi; then echo "a serial program needs MPI"; exit 1; fi
echo "ldd: no MPI library in the serial programs"
nff_view --help | head -1
mesh_view --help | head -1
gks3d-render --help | head -1
IN
chroot "$root" /bin/sh /tmp/work/test.sh
echo "deb-chroot-test: passed in $(( $(date +%s) - start )) s"
