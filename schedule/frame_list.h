// Frame lists as render farms write them (Deadline, OpenCue, Flamenco,
// OpenJD): comma-separated numbers and ranges, each range FIRST..LAST or
// FIRST-LAST with an optional step (x4 or :4), e.g. "1-240x4,300". A task
// renders the chunk of the list between its start and end, clamped to it.
#pragma once

#include <string>
#include <vector>

#include "graph/diagnostic.h"

namespace shadetree {

// The frames of `text`, ascending and without repeats, at most
// max_sequence_frames of them (graph/parse.h); frames are whole numbers
// from 0 to largest_frame.
Result<std::vector<int>> parse_frame_list(const std::string& text);

// The frames of `frames` from `start` to `end` (FIRST..LAST or FIRST-LAST);
// a chunk reaching past the list is clamped to it, one outside it holds
// no frame and is an error.
Result<std::vector<int>> frame_chunk(const std::vector<int>& frames, const std::string& chunk);

}  // namespace shadetree
