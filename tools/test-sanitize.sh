#!/usr/bin/env bash
# make test-sanitize: builds Lagoon with AddressSanitizer + UndefinedBehaviorSanitizer (and LeakSanitizer, part
# of ASan) in build-sanitize/ and runs the unit, CLI and GPU suites on lavapipe with the validation layer on.
# Any report fails the run: in the test binaries themselves and in the `lagoon` processes the CLI tests start,
# whose reports also go to build-sanitize/sanitizer-logs/ and are checked at the end (a child whose test only
# looked at its output would otherwise hide one). docs/sanitizers.md says more.
#   tools/test-sanitize.sh [ctest arguments...]     e.g. -R 'unit.Npy' to run a subset
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SANITIZE_BUILD_DIR:-build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
# GCC's flow analysis sees ASan's instrumentation and warns falsely that std::regex's state may be used
# uninitialised (a known GCC 12 false positive); the normal build keeps that warning as an error.
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -Wno-maybe-uninitialized"
mkdir -p "$build"
# dlclose that unloads nothing, so that leaks inside lavapipe, LLVM and the layer keep their names at exit.
keep_loaded=$(pwd)/$build/keep_libraries_loaded.o
cc -c -O1 tests/sanitize/keep_libraries_loaded.c -o "$keep_loaded"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLAGOON_BUILD_BENCHMARKS=OFF \
  "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags $keep_loaded" "-DCMAKE_SHARED_LINKER_FLAGS=$flags" \
  >/dev/null
cmake --build "$build" -j "$jobs" --target unit_tests gpu_tests cli_tests lagoon

logs=$(pwd)/$build/sanitizer-logs
rm -rf "$logs"
mkdir -p "$logs"
supp=$(pwd)/tests/sanitize
# detect_leaks: LeakSanitizer at exit. The suppressions cover only libraries we do not build (lsan.supp says
# which and why). Reports also go to files, so that one in a child process cannot pass unseen.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:exitcode=86:log_path=$logs/asan:log_exe_name=1:detect_stack_use_after_return=0"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0:exitcode=86"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=86:log_path=$logs/ubsan:suppressions=$supp/ubsan.supp"
start=$(date +%s)
status=0
(cd "$build" && ctest -L 'unit|cli|gpu' --output-on-failure -j "$jobs" --timeout 1200 "$@") || status=$?
reports=$(find "$logs" -type f -size +0 | sort)
if [[ -n $reports ]]; then
  echo "test-sanitize: sanitizer reports in $logs:"
  for r in $reports; do echo "== $r"; head -40 "$r"; done
  status=1
fi
echo "test-sanitize: $(( $(date +%s) - start )) s; $( [[ $status -eq 0 ]] && echo clean || echo FAILED )"
exit "$status"
