#!/usr/bin/env bash
# cueball's one entry point for people and CI, on Debian bookworm as root:
#   ./build.sh demo   install what is missing, build (Release), run the main job
#   ./build.sh test   the same, then every test (Release), then the C++ suite
#                     again under AddressSanitizer + UndefinedBehaviorSanitizer
#                     (clang; without the long numerics and searches; see below),
#                     then a bounded libFuzzer run of the scenario, table and
#                     game-state readers against the same instrumented library;
#                     the Release suite includes the HTML viewer's tests in
#                     headless Chromium (viewer/, npm packages from its lockfile)
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-demo}

packages=(g++ cmake ninja-build libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev gnuplot-nox pybind11-dev python3-dev)
packages+=(python3-numpy python3-venv python3-pip python3-setuptools python3-wheel)  # the module's dependency; pip install of it into a venv, offline
if [[ "$mode" == test ]]; then
  packages+=(clang-14 libclang-rt-14-dev llvm-14)  # libFuzzer (libclang_rt.fuzzer) and readable traces
  packages+=(chromium)                             # the viewer's end-to-end tests
  packages+=(python3-numpy python3-mypy)           # the Python module's tests: Result's arrays, mypy on the stubs
  packages+=(python3-distributed)                  # cueball.dask's test: a LocalCluster of 2 worker processes
  command -v npm >/dev/null || packages+=(nodejs npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "== installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
build() {  # build <preset> [cmake -D options]
  cmake --preset "$@" >/dev/null
  cmake --build --preset "$1" -j "$jobs"
}
phase() {  # phase <name> <command...>: runs it and says how long it took
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "== $name: $((SECONDS - start)) s"
}

case "$mode" in
  demo)
    build release -DCUEBALL_BUILD_PYTHON=ON
    bin=build/release/cueball
    echo "== cueball simulate: the built-in 9-ball break (result in build/break.json, viewer page build/break.html)"
    "$bin" simulate -o build/break.json --html build/break.html
    ;;
  test)
    phase "npm ci (viewer)" bash -c 'cd viewer && npm ci --no-audit --no-fund --loglevel=error'
    phase "release build" build release -DCUEBALL_VIEWER_TESTS=ON -DCUEBALL_BUILD_PYTHON=ON
    phase "release tests" ctest --preset release
    # The sanitizer build: clang, the library instrumented (ASan + UBSan, and
    # libFuzzer's coverage), linked with the test objects the Release build
    # compiled (tests/CMakeLists.txt, CUEBALL_TEST_OBJECTS_FROM) and with the
    # fuzz targets. It checks memory and undefined behaviour, not numbers: it
    # leaves out the tests of tests/long_numerics.cmake (long accuracy checks
    # and long searches, which the Release suite above has run in full), runs
    # a tenth of the cases of the long random scans and fewer starts of the
    # calibration's strike fits (tests/support/test_scale.hpp); every code
    # path they take still runs in it. The Python module is not built there
    # (its tests ran in Release; the bindings call the library checked here).
    # A tree configured by the asan preset of before (GCC) cannot be
    # reconfigured with clang in place: start it afresh.
    if [[ -f build/asan/CMakeCache.txt ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' build/asan/CMakeCache.txt; then
      echo "== build/asan was configured with another compiler: removing it"
      rm -rf build/asan
    fi
    phase "asan build" build asan "-DCUEBALL_TEST_OBJECTS_FROM=$PWD/build/release"
    phase "asan tests" ctest --preset asan
    phase "fuzz run" fuzz/run.sh build/asan 30
    ;;
  *)
    echo "usage: $0 [demo|test]" >&2
    exit 2
    ;;
esac
