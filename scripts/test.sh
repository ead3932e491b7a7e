#!/usr/bin/env bash
# Builds and runs the whole test suite. The host's QGIS (Debian 12: QGIS 3.22, GDAL 3.6) first,
# so that a failure shows fast: a release build with the QGIS plugin and its end-to-end tests,
# the Qt6 readiness build, the Debian package installed into a clean chroot, the core and CLI
# tests again with AddressSanitizer and UndefinedBehaviorSanitizer, and a short fuzz run. Then
# the plugin is built and tested against QGIS 3.40 LTR (Debian 13) and QGIS 3.44 (Debian sid) in
# chroots made from Debian's packages and cached outside the repository.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh qgis
jobs=$(nproc)
timings=()
stage() {  # NAME COMMAND...: runs a stage and keeps its wall time
  local name=$1 start
  shift
  echo "== $name"
  start=$(date +%s)
  "$@"
  timings+=("$name: $(( $(date +%s) - start )) s")
}

host_release() {
  # Every option is set at each stage: CMake keeps what a build folder was configured with before
  # (scripts/demo.sh builds without tests), and a stage that runs no test fails (--no-tests=error).
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=ON \
    -DTSK_BUILD_TESTS=ON -DTSK_BUILD_BENCH=ON -DTSK_SANITIZE=OFF -DTSK_FUZZ=OFF \
    -DTSK_QT6_CHECK=OFF > /dev/null
  cmake --build build -j "$jobs"
  ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"
}

qt6_readiness() {
  cmake -S . -B build-qt6 -DCMAKE_BUILD_TYPE=Release -DTSK_QT6_CHECK=ON -DTSK_BUILD_CLI=OFF \
    -DTSK_BUILD_PLUGIN=OFF -DTSK_BUILD_TESTS=OFF -DTSK_BUILD_BENCH=OFF -DTSK_SANITIZE=OFF \
    -DTSK_FUZZ=OFF > /dev/null
  cmake --build build-qt6 -j "$jobs"
  echo "Qt6 readiness: 1 passed, 0 failed"
}

debian_package() {
  rm -f build/terrain-sketch_*.deb
  cmake --build build --target package
  bash scripts/deb_install_test.sh build/terrain-sketch_*.deb
}

sanitizers() {
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DTSK_BUILD_CLI=ON -DTSK_BUILD_PLUGIN=OFF \
    -DTSK_BUILD_TESTS=ON -DTSK_BUILD_BENCH=OFF -DTSK_SANITIZE=ON -DTSK_FUZZ=OFF \
    -DTSK_QT6_CHECK=OFF > /dev/null
  cmake --build build-asan -j "$jobs"
  # Leak checking is off: GDAL keeps driver-level caches alive until exit by design.
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$jobs"
}

fuzz() {
  CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTSK_FUZZ=ON \
    -DTSK_SANITIZE=ON -DTSK_BUILD_CLI=OFF -DTSK_BUILD_PLUGIN=OFF -DTSK_BUILD_TESTS=OFF \
    -DTSK_BUILD_BENCH=OFF -DTSK_QT6_CHECK=OFF > /dev/null
  cmake --build build-fuzz -j "$jobs"
  mkdir -p build-fuzz/corpus
  # Seeds from fuzz/seeds, then 60 s of mutations; any crash, leak or trap fails the run.
  build-fuzz/fuzz/fuzz_silhouettes -max_total_time=60 -max_len=4096 -rss_limit_mb=2048 \
    -artifact_prefix=build-fuzz/ build-fuzz/corpus fuzz/seeds
  echo "fuzz: 1 passed, 0 failed"
}

stage "format (clang-format, the repo's .clang-format)" bash scripts/check_format.sh
stage "no function over 80 lines in core/, io/, cli/, plugin/" \
  python3 scripts/check_function_length.py
stage "QGIS 3.22 (host): release build and tests (core, CLI, plugin headless, qgis_process, desktop)" \
  host_release
stage "Qt6 readiness: the plugin's Qt code and translations against Qt6" qt6_readiness
stage "Debian package: built, installed into a clean chroot, run" debian_package
stage "sanitizers (ASan + UBSan): core and CLI tests" sanitizers
stage "fuzz: the core for 60 s (libFuzzer, ASan + UBSan)" fuzz
# The host's package for QGIS 3.22 goes into each newer QGIS too, which must refuse it clearly.
host_zip=$(ls build/terrain_sketch-*-qgis*.zip)
stage "QGIS 3.40 LTR (Debian 13 chroot): build and tests" \
  bash scripts/chroot_stage.sh trixie "$host_zip"
stage "QGIS 3.44 (Debian sid chroot): build and tests" bash scripts/chroot_stage.sh sid "$host_zip"

echo "== wall time of each stage"
printf '  %s\n' "${timings[@]}"
