#!/usr/bin/env bash
# Builds one of the fuzz targets that reach the physics, the console's execution, the log
# reader and the tuning-file parser (clang, libFuzzer, ASan + UBSan in every library, in build-fuzz) and runs it:
#   tests/fuzz_support/run_fuzzer.sh physics|console_exec|log|tune [seconds=600] [libFuzzer flags...]
# e.g. `... physics 3600 -jobs=2 -workers=2`. New inputs go to build-fuzz/<name>_corpus; the
# committed corpus (tests/fuzz_<folder>/corpus) is only read; crashes go to build-fuzz/<name>_*.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
name=${1:?physics, console_exec, log or tune}
seconds=${2:-600}
shift $(($# < 2 ? $# : 2))
case $name in
  physics) folder=fuzz_physics max_len=16384 ;;
  console_exec) folder=fuzz_console max_len=2048 ;;
  log) folder=fuzz_log max_len=65536 ;;
  tune) folder=fuzz_tune max_len=8192 ;;
  *) echo "unknown fuzz target '$name' (physics, console_exec, log, tune)" >&2; exit 2 ;;
esac
cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=None "-DCMAKE_CXX_FLAGS=-O1 -g" -DSTRIDE_SANITIZE=ON -DSTRIDE_FUZZ=ON \
  -DSTRIDE_BENCH=OFF >/dev/null
cmake --build build-fuzz --target "${name}_fuzzer" -j 2
mkdir -p "build-fuzz/${name}_corpus" "build-fuzz/${name}_artifacts"
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$root/.ci/lsan.supp:print_suppressions=0"
exec "build-fuzz/tests/$folder/${name}_fuzzer" -max_total_time="$seconds" -max_len="$max_len" \
  -timeout=30 -print_final_stats=1 -artifact_prefix="$root/build-fuzz/${name}_artifacts/" "$@" \
  "$root/build-fuzz/${name}_corpus" "$root/tests/$folder/corpus"
