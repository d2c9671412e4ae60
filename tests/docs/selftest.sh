#!/bin/sh
# SPDX-License-Identifier: MIT
# selftest.sh CHECK ROOT WORK -- check_docs.sh must fail when the documents (copies in
# WORK, read as its DOCROOT) carry one offence of each kind: the X11 row removed from the
# README, an option missing from it, a document naming a file that does not exist.
set -u
check=$1 root=$2 work=$3
rm -rf "$work" && mkdir -p "$work/docs" || exit 2
cp "$root/README.md" "$work/" && cp "$root/docs/WORKSTATIONS.md" "$root/docs/DESIGN.md" "$work/docs/" || exit 2
sh "$check" "$root" "$work" > "$work/ok.txt" || { echo "clean copies fail:"; cat "$work/ok.txt"; exit 1; }
grep -v '^| 210 ' "$root/README.md" | sed 's/GKS_WITH_MPI/GKS_WITH_M P I/g' > "$work/README.md"
echo 'See `src/c/no_such_file.c`.' >> "$work/docs/DESIGN.md"
if sh "$check" "$root" "$work" > "$work/bad.txt"; then echo "planted offences not found"; exit 1; fi
for want in '| 210 |' 'GKS_WITH_MPI' 'src/c/no_such_file.c'; do
    grep -qF "$want" "$work/bad.txt" || { echo "not reported: $want"; cat "$work/bad.txt"; exit 1; }
done
echo "selftest: the three planted offences are reported"
