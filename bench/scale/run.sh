#!/bin/sh
# SPDX-License-Identifier: MIT
# The large-scene curve of issue 21: bench/scale/scale for 10^4 ... 2*10^7 triangles (one FILL
# AREA 3 each, ray traced at 1024^2 with a shadow), each in its own process, with 2 threads,
# then three cold pairs of 1 and 2 threads at 4*10^6 for the whole-frame speed-up and the
# machine's cost of fresh memory (grow_probe touch); prints each goal's figure against its goal. Usage: bench/scale/run.sh [--quick] [--mesh] [--no-build] [BUILD_DIR]
#   --quick: up to 10^6 (and the speed-up at 10^6).  BUILD_DIR default build-scale (Release).
#   --mesh: instead, the mesh row of issue 38: a height field of 10^6 and 10^7 vertices (--quick:
#   10^6 only) as one QUADRILATERAL MESH 3 WITH DATA (smooth) beside the same surface as FILL
#   AREA 3 triangles (flat), each in its own process, 2 threads, 1024^2; time and peak memory
#   side by side with their ratio (goal: the mesh row at most the FILL AREA 3 row in both).
set -e
quick=0; build=1; dir=build-scale; mesh=0
for a in "$@"; do
  case "$a" in
    --quick) quick=1 ;;
    --mesh) mesh=1 ;;
    --no-build) build=0 ;;
    *) dir=$a ;;
  esac
done
src=$(cd "$(dirname "$0")/../.." && pwd)
if [ $build = 1 ]; then
  cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DGKS_BUILD_BENCHMARKS=ON > /dev/null
  cmake --build "$dir" -j2 --target scale > /dev/null
fi
bin=$(cd "$dir" && pwd)/bench/scale/scale
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
if [ $mesh = 1 ]; then
  if [ $quick = 1 ]; then sizes="1000000"; else sizes="1000000 10000000"; fi
  echo "# bench/scale/run.sh $* -- $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) CPUs"
  echo "# the mesh row: each run one process (cold), 2 threads, 1024^2; load = 1-min load average before"
  for n in $sizes; do
    for s in mesh tris; do
      sleep 4; load=$(cut -d' ' -f1 /proc/loadavg)
      line=$(cd "$out" && "$bin" "$n" -t 2 -s $s -o "$out/$s.png")
      echo "$line load=$load" | tee -a "$out/mrows"
    done
  done
  awk '
function val(s, k,   i, a, n) { n = split(s, a, " "); for (i = 1; i <= n; i++) if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
{ v = val($0, "verts"); s = val($0, "surface"); t[v, s] = val($0, "total"); r[v, s] = val($0, "rss"); b[v, s] = val($0, "B/tri"); l[v, s] = val($0, "load"); n[v] = val($0, "n"); if (!(v in seen)) { seen[v] = 1; ord[++nv] = v } }
END {
  for (i = 1; i <= nv; i++) { v = ord[i];
    printf "mesh  %s vertices, %s triangles: QUADRILATERAL MESH 3 WITH DATA %.2f s %.0f MiB (%s B/tri, load %s) | FILL AREA 3 %.2f s %.0f MiB (%s B/tri, load %s) | ratio time %.2f memory %.2f: %s\n", v, n[v], t[v, "mesh"], r[v, "mesh"], b[v, "mesh"], l[v, "mesh"], t[v, "tris"], r[v, "tris"], b[v, "tris"], l[v, "tris"], t[v, "mesh"] / t[v, "tris"], r[v, "mesh"] / r[v, "tris"], (t[v, "mesh"] + 0 <= t[v, "tris"] + 0 && r[v, "mesh"] + 0 <= r[v, "tris"] + 0 ? "met" : "NOT met") }
}' "$out/mrows"
  exit 0
fi
if [ $quick = 1 ]; then series="10000 100000 1000000"; big=1000000; sp=1000000
else series="10000 100000 1000000 4000000 10000000 20000000"; big=10000000; sp=4000000; fi
echo "# bench/scale/run.sh $* -- $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) CPUs"
echo "# each row: one process (cold: first frame), 2 threads; load = 1-min load average before"
for n in $series; do
  load=$(cut -d' ' -f1 /proc/loadavg)
  line=$(cd "$out" && "$bin" "$n" -t 2 -o "$out/s_$n.png")
  echo "$line load=$load" | tee -a "$out/rows"
done
# The speed-up: three pairs of 1 and 2 threads, each process cold (4 s after the one before:
# a VM host may back freed guest pages again only when they are next used, so a process
# started at once after another gets memory that is cheaper to touch; grow_probe touch below)
pairs=""
for k in 1 2 3; do
  sleep 4; load=$(cut -d' ' -f1 /proc/loadavg)
  one=$(cd "$out" && "$bin" "$sp" -t 1 -o "$out/s1.png")
  echo "$one threads=1 load=$load"
  echo "$one" >> "$out/split1"
  sleep 4; load=$(cut -d' ' -f1 /proc/loadavg)
  two=$(cd "$out" && "$bin" "$sp" -t 2 -o "$out/s2.png")
  echo "$two threads=2 load=$load"
  echo "$two" >> "$out/split2"
  pairs="$pairs $(echo "$one" | sed 's/.* total=\([0-9.]*\).*/\1/'):$(echo "$two" | sed 's/.* total=\([0-9.]*\).*/\1/')"
  if cmp -s "$out/s1.png" "$out/s2.png" && cmp -s "$out/s1.png" "$out/s_$sp.png"; then
    echo "# pictures of 1 and 2 threads at n=$sp: equal (cmp)"
  else echo "# pictures of 1 and 2 threads at n=$sp differ!"; fi
done
probe=$(dirname "$bin")/grow_probe
if [ -x "$probe" ]; then sleep 4; echo "# $("$probe" touch)"; fi
awk -v big="$big" -v sp="$sp" -v one="$one" -v two="$two" -v pairs="$pairs" '
function val(s, k,   i, a, n) { n = split(s, a, " "); for (i = 1; i <= n; i++) if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
{ n = val($0, "n"); t[n] = val($0, "total"); r[n] = val($0, "rss"); b[n] = val($0, "B/tri"); last = n; c[n] = val($0, "us/call"); cc[n] = val($0, "cpu_us/call"); ap[n] = val($0, "app_us/call"); u[n] = val($0, "cpu"); l[n] = val($0, "load"); ord[++nr] = n }
END {
  for (i = 1; i <= nr; i++) { n = ord[i]; printf "curve n=%s wall_us/tri=%.3f cpu_us/tri=%.3f B/tri=%s load=%s\n", n, 1e6 * t[n] / n, 1e6 * u[n] / n, b[n], l[n] }
  for (k in t) if (k + 0 >= big * 0.99 && k + 0 <= big * 1.01) kb = k;
  for (k in t) if (k + 0 >= sp * 0.99 && k + 0 <= sp * 1.01) ks = k;
  printf "goal  10^7-class frame wall, 2 threads: %.2f s at n=%s (goal <= 6 s; ratio %.2f; process CPU %s s, load %s): %s\n", t[kb], kb, t[kb] / 6, u[kb], l[kb], (t[kb] + 0 <= 6 ? "met" : "NOT met");
  printf "goal  peak RSS: %.0f MiB at n=%s (goal <= 2048 MiB; ratio %.2f): %s\n", r[kb], kb, r[kb] / 2048, (r[kb] + 0 <= 2048 ? "met" : "NOT met");
  np = split(pairs, pr, " "); list = "";
  for (i = 1; i <= np; i++) { split(pr[i], q, ":"); sr[i] = q[1] / q[2]; list = list sprintf("%s%.2f", i > 1 ? ", " : "", sr[i]) }
  for (i = 1; i <= np; i++) for (j = i + 1; j <= np; j++) if (sr[j] < sr[i]) { x = sr[i]; sr[i] = sr[j]; sr[j] = x }
  med = sr[int((np + 1) / 2)];
  printf "goal  whole-frame speed-up 1 -> 2 threads at n=%s: %.2f, the median of %d cold pairs (%s) (goal >= 1.8; ratio %.2f): %s\n", ks, med, np, list, med / 1.8, (med >= 1.8 ? "met" : "NOT met");
  printf "goal  GKS call chain: %s us per FILL AREA 3 wall at n=%s (goal <= 0.25; ratio %.2f): %s; the application thread'"'"'s CPU %s us per call (ratio %.2f), process CPU %s\n", c[kb], kb, c[kb] / 0.25, (c[kb] + 0 <= 0.25 ? "met" : "NOT met"), ap[kb], ap[kb] / 0.25, cc[kb];
  t1c = val(one, "cpu"); t2c = val(two, "cpu"); printf "info  1 -> 2 threads at n=%s by process CPU, last pair: %s s / %s s (work added by the second thread: %.0f %%)\n", ks, t1c, t2c, 100 * (t2c / t1c - 1);
  printf "info  bytes per triangle resident at n=%s: %s; largest scene in 23 GB by that: %.2g triangles\n", last, b[last], 23e9 / b[last];
}' "$out/rows"
# The split by stage of the pairs (issue 39 item 8), 1 -> 2 threads, each figure the median
# of the three pairs: wall s of the calls (the application's thread's CPU; with 2 threads the
# recording worker's CPU beside it), the build, the render and the rest of the update
# (transfer, commit before the build, composition, PNG), with the ratio of each stage.
awk '
function val(s, k,   i, a, n) { n = split(s, a, " "); for (i = 1; i <= n; i++) if (index(a[i], k "=") == 1) return substr(a[i], length(k) + 2); return "" }
function med(v, n,   i, j, x) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { x = v[i]; v[i] = v[j]; v[j] = x } return v[int((n + 1) / 2)] }
FNR == 1 { f++ }
{ k = ++m[f]; n = val($0, "n"); c[f, "calls", k] = val($0, "calls"); c[f, "build", k] = val($0, "build");
  c[f, "render", k] = val($0, "render"); c[f, "rest", k] = val($0, "update") - val($0, "build") - val($0, "render");
  c[f, "app", k] = val($0, "app_us/call") * n / 1e6; c[f, "work", k] = val($0, "calls_cpu") - c[f, "app", k];
  c[f, "uflt", k] = val($0, "upd_flt"); c[f, "cflt", k] = val($0, "calls_flt");
  c[f, "asys", k] = val($0, "app_sys"); c[f, "wsys", k] = val($0, "calls_sys") - val($0, "app_sys") }
END {
  split("calls app work build render rest cflt uflt asys wsys", st, " ");
  for (g = 1; g <= 2; g++) for (i = 1; i <= 10; i++) { for (k = 1; k <= m[g]; k++) v[k] = c[g, st[i], k]; md[g, st[i]] = med(v, m[g]) }
  printf "split 1 thread:  calls %.3f s (application CPU %.3f s), build %.3f s, render %.3f s, rest of update %.3f s; page faults calls %d, update %d\n", md[1, "calls"], md[1, "app"], md[1, "build"], md[1, "render"], md[1, "rest"], md[1, "cflt"], md[1, "uflt"];
  printf "split 2 threads: calls %.3f s (application CPU %.3f s, recording worker %.3f s; of them system CPU, mostly first touches: %.3f s, %.3f s), build %.3f s, render %.3f s, rest of update %.3f s; page faults calls %d, update %d\n", md[2, "calls"], md[2, "app"], md[2, "work"], md[2, "asys"], md[2, "wsys"], md[2, "build"], md[2, "render"], md[2, "rest"], md[2, "cflt"], md[2, "uflt"];
  printf "split ratios 1 -> 2 threads (medians of the pairs): calls %.2f, build %.2f, render %.2f, rest %.2f\n", md[1, "calls"] / md[2, "calls"], md[1, "build"] / md[2, "build"], md[1, "render"] / md[2, "render"], (md[2, "rest"] > 0 ? md[1, "rest"] / md[2, "rest"] : 0);
}' "$out/split1" "$out/split2"
