#pragma once
// A WalkRecording as bytes and back, for handing walks from worker processes to the experiment
// (same binary on both ends: native byte order, not a file format).
#include <string>
#include <string_view>

#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

std::string encode_recording(const WalkRecording& r);
// Throws stride::Error when the bytes are not a whole recording.
WalkRecording decode_recording(std::string_view bytes);

}  // namespace stride::experiments
