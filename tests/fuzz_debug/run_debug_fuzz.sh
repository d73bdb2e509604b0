#!/usr/bin/env bash
# Builds the debug-protocol decoder fuzzer with clang's libFuzzer + ASan/UBSan and runs it.
#   tests/fuzz_debug/run_debug_fuzz.sh [seconds=600] [extra libFuzzer flags...]
# New inputs go to build-fuzz/debug_corpus (the committed seeds stay untouched).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
shift || true
out=build-fuzz
mkdir -p "$out/debug_corpus" "$out/debug_artifacts"
srcs=(tests/fuzz_debug/debug_fuzzer.cpp robot/debug/wire.cpp robot/debug/msgpack_map.cpp
      robot/debug/protocol.cpp robot/debug/server_message.cpp robot/framework/type_desc.cpp
      robot/framework/value.cpp)
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -DMSGPACK_DEFAULT_API_VERSION=3 -I. -I/usr/include/eigen3 "${srcs[@]}" -o "$out/debug_fuzzer"
"$out/debug_fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 -print_final_stats=1 \
  -artifact_prefix="$out/debug_artifacts/" "$@" "$out/debug_corpus" tests/fuzz_debug/corpus
