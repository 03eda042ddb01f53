#pragma once
// --export-states FILE.csv (docs/host-driven.md, "Checking a replay"): for every rendered frame and every
// living character, its id (a replay's person: the file's id and the copy), the time, its root (x, y, z),
// heading, the clip that weighs more and that clip's playback rate; with --export-joints, those joints'
// world positions (Crowd::jointWorld), so that the motion can be checked against the recording outside the
// program. Written whole once the run ends (io::writeFile: no partial file).
#include <cstdint>
#include <string>
#include <vector>

#include <crowdgpu/crowd.hpp>

namespace app {

class ReplayDriver;

class StateExport {
public:
    // Checks the path can be written and that every joint exists (app::Error naming it).
    StateExport(std::string path, const crowdgpu::Crowd& crowd, const std::vector<std::string>& joints);
    // The frame at `time`, after the crowd was advanced to it; `replay`: names the characters' people.
    void frame(const crowdgpu::Crowd& crowd, double time, const ReplayDriver* replay);
    void write() const;
    std::size_t rows() const { return rows_; }

private:
    std::string path_;
    std::vector<std::string> jointNames_;
    std::vector<std::uint32_t> joints_;
    std::string text_;
    std::size_t rows_ = 0;
};

}  // namespace app
