#include "app/start_time.h"

#include <cmath>
#include <string>

#include "app/number_text.h"
#include "app/error.h"

namespace app {

void checkStartTime(float start, std::uint32_t count, crowdgpu::Behaviour behaviour) {
    if (behaviour == crowdgpu::Behaviour::InPlace) return;  // nothing to replan: any start is one step
    const double work = static_cast<double>(start) * count;
    if (work <= kMaxReplannedCharacterSeconds) return;
    const float latest = static_cast<float>(std::floor(kMaxReplannedCharacterSeconds / count));
    throw app::Error("--start: " + formatNumber(start) + " s is too late for " + std::to_string(count) + " " +
                     crowdgpu::behaviourName(behaviour) + " characters, which replan from 0 s to get there (at most " +
                     formatNumber(latest) + " s for --count " + std::to_string(count) + ")");
}

}  // namespace app
