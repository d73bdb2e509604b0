#!/bin/sh
# Builds the console parser fuzzer with clang's libFuzzer and runs it for N seconds (default 60).
# usage: tests/fuzz/run_console_fuzz.sh [seconds] [build dir]
set -eu
seconds=${1:-60}
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$root/build-fuzz}
mkdir -p "$build/console_fuzz_corpus" "$build/console_fuzz_artifacts"
src="$root/console/interpreter"
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I"$root" "$root/tests/fuzz/console_parser_fuzz.cpp" "$src/tokenizer.cpp" \
  "$src/edit_distance.cpp" "$src/values.cpp" "$src/command_table.cpp" "$src/command_parser.cpp" "$src/sweep_arguments.cpp" \
  -o "$build/console_parser_fuzz"
# New inputs go to the scratch corpus (first directory); the committed corpus is only read.
exec "$build/console_parser_fuzz" -max_total_time="$seconds" -print_final_stats=1 \
  -max_len=512 -artifact_prefix="$build/console_fuzz_artifacts/" \
  "$build/console_fuzz_corpus" "$root/tests/fuzz/console_corpus"
