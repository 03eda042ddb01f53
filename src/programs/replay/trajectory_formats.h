#pragma once
// One reader per format (each in its own .cpp), behind replay::readTrajectories, which finds the
// format and calls one. Each returns the rows as tracks (replay/track_assembly.h) or throws app::Error
// "PATH:LINE: problem"; a file with no rows is an empty recording, not an error.
#include <string>
#include <string_view>

#include "replay/trajectory.h"
#include "replay/trajectory_options.h"

namespace replay {

// PeTrack / Jülich archive text: "#" comments (among them "# framerate: 25 fps" and a column line
// "# id frame x/cm y/cm z/cm"), then whitespace-separated "id frame x y [z]" rows; z (head height) unread.
Recording readPeTrack(const std::string& path, std::string_view text, const ReadOptions& options);

// ETH/UCY obsmat.txt: whitespace-separated "frame id x z y vx vz vy" in metres, the ground in columns 3
// and 5; frames count video frames annotated every 0.4 s.
Recording readObsmat(const std::string& path, std::string_view text, const ReadOptions& options);

// CSV whose header names id, frame or time (seconds), x and y, in any case and order.
Recording readCsv(const std::string& path, std::string_view text, const ReadOptions& options);

// JuPedSim's SQLite output: trajectory_data(frame, id, pos_x, pos_y, ...) and metadata(key, value) with fps.
Recording readJuPedSim(const std::string& path, const ReadOptions& options);

// ETH/UCY annotate positions every 0.4 s of video, whatever the video's rate.
inline constexpr double kObsmatIntervalSeconds = 0.4;

}  // namespace replay
