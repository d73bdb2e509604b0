#!/usr/bin/env bash
# Builds the sweep decoders' fuzzer (libFuzzer + ASan/UBSan, clang) and runs it.
#   tests/fuzz_sweep/run_sweep_fuzz.sh [seconds=600]
# New inputs go to build-fuzz-sweep/corpus (the committed seeds stay untouched).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
out=build-fuzz-sweep
cmake -S . -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ "-DCMAKE_CXX_FLAGS=-O1 -g -fsanitize=fuzzer-no-link,address,undefined" \
  -DSTRIDE_FUZZ=ON -DSTRIDE_TESTS=ON -DSTRIDE_BENCH=OFF > /dev/null
cmake --build "$out" -j 2 --target sweep_fuzzer
mkdir -p "$out/corpus"
"$out/tests/fuzz_sweep/sweep_fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  "$out/corpus" tests/fuzz_sweep/corpus
