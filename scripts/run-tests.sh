#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# run-tests.sh -- set up, then run the whole test suite in four builds:
#   ./build-test  Debug at -Og (the tests of the tracer run several times faster than at -O0,
#                 the times are in docs/bench/RESULTS.md, "The test suite"), -DGKS_WERROR=ON,
#                 every optional dependency found, benchmarks built too (not run); its ctest
#                 runs the tests that no later stage runs as they run here: the checks of
#                 sources and documents (label nocode), and the installed package's link lines
#                 and the README's programs without sanitizer flags (label linkline:
#                 install_*, readme_*).
#                 Every other test runs in ./build-asan (the same dependencies, under
#                 AddressSanitizer + UBSan) and, where it needs no optional dependency, in
#                 ./build-min (plain, -O2)
#   ./build-min   Release (-O2, so that warnings only the optimizer finds, such as
#                 -Wmaybe-uninitialized, fail too), -DGKS_WERROR=ON, every optional dependency
#                 off (each GKS_WITH_* option, the Fortran binding included), benchmarks off;
#                 then the benchmarks are built there as well, so that their code without any
#                 peer compiles; the checks of sources and documents (ctest label nocode,
#                 the same in every build) are left out
#   ./build-asan  Debug at -O1 (AddressSanitizer's documentation advises -O1 or more for
#                 speed; the times are in docs/bench/RESULTS.md), -DGKS_WERROR=ON
#                 -DGKS_SANITIZE=ON (AddressSanitizer + UBSan, LeakSanitizer on when it works
#                 here, see below);
#                 the checks of sources and documents (ctest label nocode) are left out
#   ./build-tsan  RelWithDebInfo, -DGKS_TSAN=ON (ThreadSanitizer): only the tests that run
#                 threads (the tracer's pool, the recording worker and its failure paths,
#                 the thread rule), built as their own targets so that the stage stays short
# then fuzzes the untrusted-input readers for FUZZ_SECONDS (default 30) per target.
# Each ctest runs two tests at a time (-j2, the machine's two cores); a fresh build has no times
# of an earlier run, so the longest tests carry a COST (tests/*/CMakeLists.txt) that makes
# ctest start them first rather than last beside an idle core.
# The gcc builds with -g (Debug, sanitizer, ThreadSanitizer) leave out variable tracking
# (-fno-var-tracking): file and line in every report and backtrace stay, a debugger may show
# fewer variables' values; gcc spent about a third of the sanitizer build on it (the times
# are in docs/bench/RESULTS.md, "The test suite").
# Exits non-zero on any build or test failure. The tests are asked for explicitly
# (-DBUILD_TESTING=ON, the Release build-min would not build them by default) and required
# (-DGKS_REQUIRE_TESTS=ON: a missing cmocka stops the configure instead of skipping them).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's line says when it starts, in seconds since the script started (bash's SECONDS).
stage() { echo "=== run-tests (${SECONDS} s): $*"; }
scripts/setup.sh

stage "Debug build with -Werror (build-test)"
tests=(-DBUILD_TESTING=ON -DGKS_REQUIRE_TESTS=ON)
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-g -Og -fno-var-tracking" \
      -DGKS_WERROR=ON -DGKS_SANITIZE=OFF \
      -DGKS_BUILD_BENCHMARKS=ON "${tests[@]}"
cmake --build build-test -j2
ctest --test-dir build-test --output-on-failure -j2 --no-tests=error -L '^(nocode|linkline)$'

# Every GKS_WITH_* option that the project defines (read from the cache, so that a new
# optional dependency is switched off here without editing this script).
off=()
while IFS= read -r name; do off+=("-D$name=OFF"); done < <(
    sed -n 's/^\(GKS_WITH_[A-Z0-9_]*\):BOOL=.*/\1/p' build-test/CMakeCache.txt | sort)
stage "every optional dependency off (build-min): ${off[*]}"
cmake -S . -B build-min -DCMAKE_BUILD_TYPE=Release -DGKS_WERROR=ON -DGKS_SANITIZE=OFF \
      -DGKS_BUILD_BENCHMARKS=OFF "${tests[@]}" "${off[@]}"
cmake --build build-min -j2
ctest --test-dir build-min --output-on-failure -j2 -LE nocode
cmake -S . -B build-min -DGKS_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build-min -j2

stage "sanitizer build (build-asan)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-g -O1 -fno-var-tracking" \
      -DGKS_WERROR=ON -DGKS_SANITIZE=ON "${tests[@]}"
cmake --build build-asan -j2
# LeakSanitizer needs ptrace-like access that some containers deny; probe it with a
# tiny leaking program and enable leak detection only if LSan can actually run.
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf '#include <stdlib.h>\nint main(void){void *p=malloc(7);p=0;return 0;}\n' >"$probe/leak.c"
detect_leaks=0
if cc -fsanitize=address -o "$probe/leak" "$probe/leak.c" 2>/dev/null; then
    if ! ASAN_OPTIONS=detect_leaks=1 "$probe/leak" >"$probe/out" 2>&1 &&
       grep -q 'ERROR: LeakSanitizer: detected memory leaks' "$probe/out"; then
        detect_leaks=1
    fi
fi
if [ "$detect_leaks" = 1 ]; then
    echo "run-tests: LeakSanitizer works here: detect_leaks=1"
else
    echo "run-tests: LeakSanitizer unavailable here (e.g. ptrace denied): detect_leaks=0"
fi
export ASAN_OPTIONS="detect_leaks=$detect_leaks"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The checks of the sources and documents (label nocode) run none of the library's code: they
# ran in the first stage.
ctest --test-dir build-asan --output-on-failure -j2 -LE nocode

stage "ThreadSanitizer build (build-tsan), the threaded tests"
unset ASAN_OPTIONS
tsan_targets=(test_threads test_raytrace test_rt_oom test_rt_pool test_rt_render test_rt_tiles
              test_rt_isect test_rt_smooth test_rt_cubes test_rt_buildparts)
tsan_tests='^(core_test_threads|core_test_raytrace|core_test_rt_oom|rt_(pool|render|tiles|isect|smooth|cubes|buildparts))$'
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g -DNDEBUG -fno-var-tracking" -DGKS_WERROR=ON -DGKS_SANITIZE=OFF \
      -DGKS_TSAN=ON -DGKS_BUILD_BENCHMARKS=OFF -DGKS_BUILD_EXAMPLES=OFF "${tests[@]}"
cmake --build build-tsan -j2 --target "${tsan_targets[@]}"
# halt_on_error: the first data race fails the test (exit code 66).
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" \
    ctest --test-dir build-tsan --output-on-failure --no-tests=error -j2 -R "$tsan_tests"

stage "fuzzing the untrusted-input readers (libFuzzer, ${FUZZ_SECONDS:-30} s a target)"
scripts/fuzz.sh "${FUZZ_SECONDS:-30}"
stage "all passed"
