#pragma once
// Reading a trajectory file of any supported format into a Recording (replay/trajectory.h). The
// format is found from the content, so a renamed file still reads: SQLite's magic bytes are
// JuPedSim, a comma-separated header naming id, x and y is CSV, a "#" comment is PeTrack, and a
// first row of 8 numbers is ETH/UCY obsmat, of 4 or 5 PeTrack without comments.
#include <string>
#include <string_view>

#include "replay/trajectory.h"
#include "replay/trajectory_options.h"

namespace replay {

// Reads `path` in options.format (Auto: detected). Rows out of time order within a person are
// sorted by frame. Throws app::Error with one line, "PATH:LINE: problem" for bad content (a field that
// is no number or not finite, too few columns, a header without x or y, a person twice at one frame)
// and "PATH: problem; give --trajectory-fps" (or -units) when the file lacks what the flags supply.
// An empty file, or one of comments only, is an empty recording.
Recording readTrajectories(const std::string& path, const ReadOptions& options = {});

// The format of a file whose first bytes (or whole text) are `content`; throws app::Error
// "PATH:LINE: cannot tell the format ...; give --trajectory-format" when nothing fits. Content with
// no line but blanks and comments is PeTrack's (an empty recording whatever the format).
Format detectFormat(const std::string& path, std::string_view content);

}  // namespace replay
