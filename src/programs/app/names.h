#pragma once
// The command line's names of the library's choices (methods, culling, animation, behaviours): the
// library names them (crowdgpu::methodName, ...); the programs parse them back.
#include <string>
#include <vector>

#include <crowdgpu/renderer.hpp>

namespace app {

inline constexpr int kLodCount = 3;  // mesh levels of detail (crowdgpu::FrameCounts)

// Every skinning method, in the order the benchmark lists them.
const std::vector<crowdgpu::Method>& allMethods();
// The methods' names joined by ", ".
std::string methodList();

// Each returns false for a name it does not know and leaves `out` as it was.
bool parseMethod(const std::string& name, crowdgpu::Method& out);
bool parseCulling(const std::string& name, crowdgpu::Culling& out);
bool parseShadowRaster(const std::string& name, crowdgpu::ShadowRaster& out);
bool parseAnimation(const std::string& name, crowdgpu::Animation& out);
bool parseBehaviour(const std::string& name, crowdgpu::Behaviour& out);

}  // namespace app
