#!/usr/bin/env bash
# Builds and runs the whole test suite: a release build with the QGIS plugin and its end-to-end
# tests, then the core and CLI tests again with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh qgis
jobs=$(nproc)

echo "== format (clang-format, the repo's .clang-format)"
bash scripts/check_format.sh

# Every option is set at each stage: CMake keeps what a build folder was configured with before
# (scripts/demo.sh builds without tests), and a stage that runs no test fails (--no-tests=error).
echo "== release build and tests (core, CLI, QGIS plugin headless, qgis_process, desktop)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=ON \
  -DTSK_BUILD_TESTS=ON -DTSK_BUILD_BENCH=ON -DTSK_SANITIZE=OFF -DTSK_FUZZ=OFF > /dev/null
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"

echo "== sanitizer build (ASan + UBSan) of the core and CLI, and their tests"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=OFF \
  -DTSK_BUILD_TESTS=ON -DTSK_BUILD_BENCH=OFF -DTSK_SANITIZE=ON -DTSK_FUZZ=OFF > /dev/null
cmake --build build-asan -j "$jobs"
# Leak checking is off: GDAL keeps driver-level caches alive until exit by design.
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$jobs"

echo "== short fuzz run of the core (libFuzzer, ASan + UBSan)"
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSK_FUZZ=ON \
  -DTSK_SANITIZE=ON -DTSK_BUILD_CLI=OFF -DTSK_BUILD_PLUGIN=OFF -DTSK_BUILD_TESTS=OFF \
  -DTSK_BUILD_BENCH=OFF > /dev/null
cmake --build build-fuzz -j "$jobs"
mkdir -p build-fuzz/corpus
# Seeds from fuzz/seeds, then 60 s of mutations; any crash, leak or trap fails the run.
build-fuzz/fuzz/fuzz_silhouettes -max_total_time=60 -max_len=4096 -rss_limit_mb=2048 \
  -artifact_prefix=build-fuzz/ build-fuzz/corpus fuzz/seeds
echo "fuzz: 1 passed, 0 failed"
