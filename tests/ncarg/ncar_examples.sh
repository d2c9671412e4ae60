#!/bin/sh
# SPDX-License-Identifier: MIT
# ncar_examples.sh CMP CTRANS BINDIR NAME... -- for each NCAR example NAME: run NCAR's build
# (BINDIR/ref_NAME: NCGM gmeta, translated by ctrans to 1024x1024 Sun rasters) and gks3d's
# (BINDIR/ncar_NAME: PNG frames by the profile's default type mapping), then compare the
# frames (CMP = ncar_cmp; tolerance there). Fails on a frame that differs, a different
# frame count, a non-zero exit or any GKS error line of gks3d's run.
set -u
cmp=$1 ctrans=$2 bin=$3
shift 3
unset DISPLAY GKS3D_WS_TYPES GKS3D_ASF
status=0
for ex in "$@"; do
    d=$bin/run_$ex
    rm -rf "$d" && mkdir -p "$d/ref" "$d/out" || exit 1
    (cd "$d/ref" && "$bin/ref_$ex" > log.txt 2>&1 < /dev/null) ||
        { echo "$ex: NCAR's build failed to run"; status=1; continue; }
    "$ctrans" -d sun -res 1024x1024 "$d/ref/gmeta" > "$d/ref/ref.ras" 2> "$d/ref/ctrans.txt" ||
        { echo "$ex: ctrans failed"; status=1; continue; }
    (cd "$d/out" && "$bin/ncar_$ex" > log.txt 2>&1 < /dev/null) ||
        { echo "$ex: gks3d's build exited non-zero"; status=1; }
    n=$(grep -c "GKS ERROR" "$d/out/log.txt")
    if [ "$n" -ne 0 ]; then
        echo "$ex: $n GKS error lines:"; grep "GKS ERROR" "$d/out/log.txt" | sort | uniq -c | head -5
        status=1
    fi
    # Frames in order: B.png, B-002.png, B-003.png, ...
    first=$(cd "$d/out" && ls *.png 2>/dev/null | grep -v -- '-[0-9][0-9][0-9]\.png$' | head -1)
    if [ -z "$first" ]; then
        echo "$ex: gks3d wrote no frame"; status=1; continue
    fi
    base=${first%.png}
    frames="$d/out/$first $(cd "$d/out" && ls "$base"-[0-9][0-9][0-9].png 2>/dev/null | sed "s|^|$d/out/|" | tr '\n' ' ')"
    echo "$ex:"
    # shellcheck disable=SC2086 # frames: a list of paths without blanks
    "$cmp" "$d/ref/ref.ras" $frames > "$d/cmp.txt" || status=1
    sed 's/^/  /' "$d/cmp.txt"
done
exit $status
