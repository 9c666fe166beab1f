#!/usr/bin/env bash
# Bounded libFuzzer run of cueball's JSON readers, for CI and by hand.
#
#   fuzz/run.sh [BUILD_DIR] [SECONDS]
#
# BUILD_DIR is the "asan" preset's build directory (default build/asan; the
# binaries are in BUILD_DIR/fuzz or BUILD_DIR). SECONDS (default 30) is the
# fuzzing time in total: half for fuzz_scenario, a quarter each for
# fuzz_table and fuzz_game_state. Each target first runs every seed in full, then fuzzes from
# them; new inputs go to a scratch corpus under BUILD_DIR (fuzz/corpus/ in the
# source tree is never written). Exits non-zero on any crash, sanitizer
# report, unexpected exception, broken invariant, timeout (> 10 s for one
# input) or memory blow-up; the reproducer is written to
# BUILD_DIR/fuzz-artifacts/ and its path printed.
# Environment: FUZZ_SEED (libFuzzer -seed, default random), FUZZ_JOBS (run
# the targets side by side, each for SECONDS, when 2; default 1).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-build/asan}
seconds=${2:-30}
[[ $seconds =~ ^[0-9]+$ ]] || { echo "usage: $0 [BUILD_DIR] [SECONDS]" >&2; exit 2; }

find_bin() {
  for candidate in "$build/fuzz/$1" "$build/$1"; do
    [[ -x $candidate ]] && { echo "$candidate"; return; }
  done
  echo "fuzz/run.sh: $1 not found in $build (build the 'asan' preset first)" >&2
  exit 2
}

# Symbolized stack traces: llvm-symbolizer (package llvm-14) if present.
for s in /usr/lib/llvm-14/bin/llvm-symbolizer "$(command -v llvm-symbolizer || true)"; do
  if [[ -n $s && -x $s ]]; then export ASAN_SYMBOLIZER_PATH=$s; break; fi
done
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

artifacts="$build/fuzz-artifacts"
mkdir -p "$artifacts"

fuzz_one() {  # fuzz_one <target> <corpus name> <seconds>
  local bin work log status
  bin=$(find_bin "$1")
  work="$build/fuzz-corpus/$2"
  log="$build/fuzz-$1.log"
  mkdir -p "$work"
  local args=(-max_total_time="$3" -timeout=10 -rss_limit_mb=2048 -max_len=8192
              -dict="$here/json.dict" -artifact_prefix="$artifacts/$1-" -print_final_stats=1)
  [[ -n ${FUZZ_SEED:-} ]] && args+=(-seed="$FUZZ_SEED")
  echo "== fuzz: $1 for $3 s (seeds: fuzz/corpus/$2, log: $log)"
  status=0
  # Every seed in full first (while fuzzing, inputs are cut to -max_len).
  "$bin" -timeout=10 -rss_limit_mb=2048 "$here/corpus/$2"/* >"$log" 2>&1 || status=$?
  ((status != 0)) || "$bin" "${args[@]}" "$work" "$here/corpus/$2" >>"$log" 2>&1 || status=$?
  grep -E "^(#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb)|INITED" "$log" | sed 's/^/   /' || true
  if ((status != 0)); then
    echo "== fuzz: $1 FAILED (exit $status); full log: $log" >&2
    # The report without the thousand frames of a stack overflow.
    grep -E "Running: " "$log" | tail -n 1 >&2 || true
    grep -E "ERROR: |SUMMARY: |runtime error|\*\*\* cueball fuzz|terminate called|what\(\)|deadly signal|Test unit written|out-of-memory|timeout" \
      "$log" | tail -n 12 | cut -c1-400 >&2 || true
    grep -E "^ +#[0-9]+ " "$log" | grep -E "cueball|LLVMFuzzerTestOneInput" | head -n 15 | cut -c1-300 >&2 || true
    return 1
  fi
}

scenario_time=$(( seconds / 2 ))
table_time=$(( seconds / 4 ))
game_time=$(( seconds - scenario_time - table_time ))
((scenario_time > 0)) || scenario_time=1
((table_time > 0)) || table_time=1
((game_time > 0)) || game_time=1

if [[ ${FUZZ_JOBS:-1} == 2 ]]; then
  fuzz_one fuzz_scenario scenario "$seconds" & p1=$!
  fuzz_one fuzz_table table "$seconds" & p2=$!
  fuzz_one fuzz_game_state game_state "$seconds" & p3=$!
  rc=0
  wait "$p1" || rc=1
  wait "$p2" || rc=1
  wait "$p3" || rc=1
  ((rc == 0)) && echo "== fuzz: no crash in $seconds s (each target)"
  exit "$rc"
fi
fuzz_one fuzz_scenario scenario "$scenario_time"
fuzz_one fuzz_table table "$table_time"
fuzz_one fuzz_game_state game_state "$game_time"
echo "== fuzz: no crash in $seconds s"
