#!/usr/bin/env bash
# Runs one fuzz target: replays its saved regression inputs (tests/fuzz/regressions/TARGET/), then fuzzes
# for SECONDS from a scratch copy of its seed corpus (tests/fuzz/corpus/TARGET/; the source tree is never
# written). A crash, a leak, a hang over 10 s or more than 2 GiB of memory fails it, and the input is saved
# in WORKDIR/crashes/. Prints the executions run.
#   run_fuzzer.sh BINARY TARGET SECONDS WORKDIR
set -euo pipefail
binary=$1 target=$2 seconds=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
[[ -x $binary ]] || { echo "fuzz: $binary is not built" >&2; exit 1; }
rm -rf "$work/corpus"
mkdir -p "$work/corpus" "$work/crashes"
cp "$here/corpus/$target"/* "$work/corpus/"

mapfile -t regressions < <(find "$here/regressions/$target" -type f ! -name .gitkeep | sort)
if (( ${#regressions[@]} > 0 )); then
  "$binary" -rss_limit_mb=2048 -timeout=10 "${regressions[@]}" >"$work/regressions.log" 2>&1 ||
    { cat "$work/regressions.log"; echo "fuzz_$target: a saved regression input fails again" >&2; exit 1; }
  echo "fuzz_$target: ${#regressions[@]} regression input(s) pass"
fi

status=0
"$binary" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
  -artifact_prefix="$work/crashes/" "$work/corpus" >"$work/fuzz.log" 2>&1 || status=$?
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/fuzz.log" | tail -1)
echo "fuzz_$target: ${runs:-0} executions in ${seconds} s, corpus $(find "$work/corpus" -type f | wc -l) inputs"
if (( status != 0 )); then
  tail -60 "$work/fuzz.log"
  echo "fuzz_$target: FAILED; the input is in $work/crashes/. Fix the cause, then copy the input into" \
    "tests/fuzz/regressions/$target/ so that every later run replays it." >&2
fi
exit "$status"
