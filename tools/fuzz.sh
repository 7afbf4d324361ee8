#!/usr/bin/env bash
# make fuzz: builds the libFuzzer targets (tests/fuzz) with clang-14 into build-fuzz/ and runs each for
# SECONDS (default 60). Crash inputs land in build-fuzz/work/TARGET/crashes/; docs/fuzzing.md says what next.
#   tools/fuzz.sh [SECONDS [TARGET...]]      targets: scene gltf image npy demo_script
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
(( ${#targets[@]} > 0 )) || targets=(scene gltf image npy demo_script)
clang=$(command -v clang++-14 || true)
[[ -n $clang ]] || { echo "fuzz: clang++-14 not found; run tools/install-deps.sh" >&2; exit 1; }
cmake -S tests/fuzz -B build-fuzz -DCMAKE_CXX_COMPILER="$clang" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)"
failed=()
for t in "${targets[@]}"; do
  bash tests/fuzz/run_fuzzer.sh "build-fuzz/fuzz_$t" "$t" "$seconds" "build-fuzz/work/$t" || failed+=("$t")
done
if (( ${#failed[@]} > 0 )); then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} target(s), ${seconds} s each, no crash"
