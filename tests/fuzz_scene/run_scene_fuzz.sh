#!/usr/bin/env bash
# Builds the scene/URDF parser fuzzer with clang's libFuzzer + ASan/UBSan and runs it.
#   tests/fuzz_scene/run_scene_fuzz.sh [seconds=600]
# New inputs go to build-fuzz/scene_corpus (the committed seeds stay untouched).
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
out=build-fuzz
mkdir -p "$out/scene_corpus"
srcs=(tests/fuzz_scene/scene_fuzzer.cpp simulator/scene/scene_parser.cpp robot/core/units.cpp
      robot/core/xml_element.cpp robot/model/urdf_loader.cpp robot/model/urdf_validation.cpp
      robot/model/robot_model.cpp)
clang++ -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -I. -I/usr/include/eigen3 \
  "${srcs[@]}" -ltinyxml2 $(pkg-config --libs urdfdom) -o "$out/scene_fuzzer"
"$out/scene_fuzzer" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  "$out/scene_corpus" tests/fuzz_scene/corpus
