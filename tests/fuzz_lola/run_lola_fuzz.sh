#!/usr/bin/env bash
# Builds the LoLA packet decoder fuzzer with clang's libFuzzer + ASan/UBSan and runs it.
#   tests/fuzz_lola/run_lola_fuzz.sh [seconds=600] [extra libFuzzer options...]
# New inputs go to build-fuzz/lola_corpus (the committed seeds stay untouched).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
shift || true
out=build-fuzz
mkdir -p "$out/lola_corpus" "$out/lola_artifacts"
srcs=(tests/fuzz_lola/lola_fuzzer.cpp robot/hal/lola/sensor_packet.cpp
      robot/hal/lola/actuator_packet.cpp robot/hal/lola/msgpack_fields.cpp
      robot/hal/lola/packet_stream.cpp)
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -DMSGPACK_DEFAULT_API_VERSION=3 -I. "${srcs[@]}" -o "$out/lola_fuzzer"
"$out/lola_fuzzer" -max_total_time="$seconds" -max_len=2048 -timeout=10 -print_final_stats=1 \
  -artifact_prefix="$out/lola_artifacts/" "$@" "$out/lola_corpus" tests/fuzz_lola/corpus
