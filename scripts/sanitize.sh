#!/usr/bin/env bash
# Builds the tests (the examples too with DFP_SANITIZE_EXAMPLES=ON; never the benchmarks) with
# AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/ at the repository root,
# and runs them with ctest.
# Exits non-zero on any sanitizer finding: UBSan is built without recovery and halts on
# error, ASan aborts on the first error, LeakSanitizer fails the program at exit.
# Usage: scripts/sanitize.sh   (from any directory)
# Environment: DFP_SANITIZE_OPT (optimization level, default -O0: with ASan and UBSan, GCC
#              compiles these CGAL-heavy files 2 to 3 times faster than at -O1, and the
#              tests still run in seconds), DFP_SANITIZE_EXAMPLES=ON (build and run the
#              examples too; off by default to keep CI short), DFP_SANITIZE_TIMEOUT (per
#              test, seconds; default 900), DFP_FUZZ_CASES (cases of the differential fuzzer;
#              default 500), DFP_SANITIZE_TESTS (test programs to build and run, separated
#              by spaces, e.g. "test_fuzz_differential test_reliability"; default: all of them).
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/install_dependencies.sh

opt=${DFP_SANITIZE_OPT:--O0}
tests=${DFP_SANITIZE_TESTS:-}
# Debug keeps CGAL's and the package's assertions on; -g and ${opt} replace CMake's -O0.
# DFP_TESTS makes the named tests the only ones built, so that -j2 compiles them two at a time.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug \
  "-DCMAKE_CXX_FLAGS_DEBUG=-g ${opt}" \
  -DDFP_SANITIZE=ON \
  -DDFP_BUILD_EXAMPLES="${DFP_SANITIZE_EXAMPLES:-OFF}" \
  -DDFP_BUILD_BENCHMARKS=OFF \
  -DDFP_TEST_SUITES=OFF \
  "-DDFP_TESTS=$(echo $tests | tr ' ' ';')" \
  -DCGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE=TRUE
cmake --build build-sanitize -j2
if [ -n "$tests" ]; then
  # dfp_command_line: the tool dfp (built whenever DFP_BUILD_CLI is on) on files.
  only="^(compilation_of__|execution___of__)($(echo $tests | tr ' ' '|'))\$|^dfp_command_line\$"
else
  only=""
fi

supp="$PWD/scripts/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

# The fuzzer's fixed set of cases, shortened: unoptimized and instrumented code runs about ten
# times slower.
export DFP_FUZZ_CASES="${DFP_FUZZ_CASES:-500}"

cd build-sanitize
ctest --output-on-failure -j2 --timeout "${DFP_SANITIZE_TIMEOUT:-900}" ${only:+-R "$only"}
