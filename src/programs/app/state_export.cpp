#include "app/state_export.h"

#include <cmath>
#include <cstdio>

#include "app/error.h"
#include "app/replay_driver.h"
#include "io/output_file.h"

namespace app {

StateExport::StateExport(std::string path, const crowdgpu::Crowd& crowd, const std::vector<std::string>& joints)
    : path_(std::move(path)), jointNames_(joints) {
    io::checkWritable(path_);
    const crowdgpu::Model& model = crowd.models().front();
    for (const std::string& name : joints) {
        const std::int32_t joint = model.findJoint(name);
        if (joint < 0) throw Error("--export-joints: " + model.name() + " has no joint '" + name + "'");
        joints_.push_back(static_cast<std::uint32_t>(joint));
    }
    text_ = "id,copy,slot,time,x,y,z,heading,clip,rate";
    for (const std::string& name : joints) text_ += "," + name + "_x," + name + "_y," + name + "_z";
    text_ += "\n";
}

void StateExport::frame(const crowdgpu::Crowd& crowd, double time, const ReplayDriver* replay) {
    // The rate from the phase a little before (a crossfade's rate is the blend of its two clips').
    constexpr double kStep = 1.0 / 240.0;
    char line[256];
    for (std::uint32_t slot = 0; slot < crowd.size(); ++slot) {
        std::int64_t id = slot, copy = 0;
        if (replay) {
            const std::int64_t track = replay->trackOf(slot);
            if (track < 0) continue;
            const auto& placement = replay->feed().placement(static_cast<std::uint32_t>(track));
            id = replay->feed().recording().tracks[placement.track].id;
            copy = placement.copy;
        }
        crowdgpu::CharacterState now{}, before{};
        try {
            now = crowd.stateAt(slot, time);
            before = crowd.stateAt(slot, time - kStep);
        } catch (const crowdgpu::Error&) {  // a free slot, or one the CPU does not know (device-driven)
            continue;
        }
        const std::uint32_t clip = now.weight < 0.5f ? now.clipFrom : now.clipTo;
        const crowdgpu::Model& model = crowd.models()[crowd.character(slot).model];
        // A driven character's phase is kept within a cycle at each key: the step's fraction of a cycle.
        double step = static_cast<double>(now.phase) - static_cast<double>(before.phase);
        step -= std::floor(step);
        const double cycles = step / kStep;
        const double rate = cycles * model.clipDuration(clip);
        std::snprintf(line, sizeof line, "%lld,%lld,%u,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%.4f", static_cast<long long>(id),
                      static_cast<long long>(copy), slot, time, now.position[0], now.position[1], now.position[2],
                      now.heading, model.clipName(clip).c_str(), rate);
        text_ += line;
        for (const std::uint32_t joint : joints_) {
            float rows[12];
            crowd.jointWorld(slot, joint, time, rows);
            std::snprintf(line, sizeof line, ",%.4f,%.4f,%.4f", rows[3], rows[7], rows[11]);
            text_ += line;
        }
        text_ += "\n";
        ++rows_;
    }
}

void StateExport::write() const { io::writeFile(path_, text_); }

}  // namespace app
