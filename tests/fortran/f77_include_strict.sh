#!/bin/sh
# SPDX-License-Identifier: MIT
# f77_include_strict.sh FC FILE... -- each INCLUDE file is strict fixed-form FORTRAN 77:
# comment lines start with C or * in column 1 (no "!" comments), statement lines keep
# columns 1-6 blank and end by column 72, statements use the FORTRAN 77 character set
# (upper-case letters, digits, blank and = + - * / ( ) , . ' :), declared names have at
# most 6 characters. Then a program including every file compiles with FC as fixed-form
# legacy code, -Wall -Werror.
fc=$1
shift
bad=0
n=0
for f in "$@"; do
    n=$((n + 1))
    awk -v F="$f" '
        /^[Cc*]/ { if (length($0) > 72) { print F ":" FNR ": comment beyond column 72"; bad++ }; next }
        {
            if (length($0) > 72) { print F ":" FNR ": beyond column 72"; bad++ }
            if ($0 ~ /\t/) { print F ":" FNR ": tab"; bad++ }
            if (substr($0, 1, 6) != "      ") { print F ":" FNR ": columns 1-6 not blank"; bad++ }
            if ($0 ~ /[^A-Z0-9 =+*\/(),.'"'"':-]/) { print F ":" FNR ": not FORTRAN 77 characters"; bad++ }
            s = $0
            sub(/^ *(INTEGER|PARAMETER) */, "", s)
            gsub(/[(),=+-]/, " ", s)
            k = split(s, w, " ")
            for (i = 1; i <= k; i++)
                if (w[i] ~ /^[A-Z][A-Z0-9]*$/ && length(w[i]) > 6) {
                    print F ":" FNR ": name " w[i] " longer than 6"; bad++
                }
        }
        END { exit bad > 0 }' "$f" || bad=1
done
dir=$(mktemp -d)
{
    printf '      PROGRAM STRICT\n      IMPLICIT NONE\n'
    for f in "$@"; do printf "      INCLUDE '%s'\n" "$(basename "$f")"; done
    printf '      WRITE (*, *) GBUNDL\n      END\n'
} > "$dir/strict.f"
incs=""
for f in "$@"; do incs="$incs -I$(dirname "$f")"; done
# shellcheck disable=SC2086
"$fc" $incs -std=legacy -ffixed-form -ffixed-line-length-72 -Wall -Wextra -Werror \
    -Wno-unused-parameter -c "$dir/strict.f" -o "$dir/strict.o" || bad=1
rm -rf "$dir"
[ "$bad" = 0 ] && echo "$n files strict F77"
exit "$bad"
