#!/usr/bin/env bash
# Installs what is missing, builds everything with AddressSanitizer and UndefinedBehaviorSanitizer,
# and runs every test (unit, physics, FMI conformance over every .fmu the build makes), then each
# libFuzzer target briefly (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --firmware
# Format first: it takes a second and a misformatted file fails the run before the long build.
bash scripts/format.sh --check
build=${PVATT_TEST_BUILD_DIR:-build-sanitize}
# CMakePresets.json. Clang, not GCC: it compiles this build in about half of GCC's CPU (CONTRIBUTING.md,
# "CI and its time"). Debug information is line tables only (-g1): a sanitizer report still names file and
# line, and the filter's translation unit (one of the heaviest) compiles a fifth faster, its object 63 MB -> 13 MB.
# The test programs reuse one precompiled GoogleTest + Eigen header and compile their own sources at -O1
# (cmake/test_programs.cmake; CONTRIBUTING.md, "CI and its time").
cmake --preset sanitize -B "$build"
cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
# Every fuzz target of fuzz/ for a short fixed time (10 s each, two at a time), in its own clang build.
# A smoke run against regressions; scripts/fuzz.sh with its default 60 s per target is the longer search.
bash scripts/fuzz.sh "${PVATT_FUZZ_SECONDS:-10}"
