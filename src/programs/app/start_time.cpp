#include "app/start_time.h"

#include <charconv>
#include <cmath>

#include "app/number_text.h"
#include "app/error.h"

namespace app {

double parseStartSeconds(const std::string& flag, const std::string& text) {
    double seconds = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, seconds);
    if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(seconds))
        throw app::Error(flag + ": '" + text + "' is not a number");
    if (seconds < 0.0 || seconds > kMaxStartSeconds)
        throw app::Error(flag + ": " + text + " is outside 0.." + formatNumber(kMaxStartSeconds));
    return seconds;
}

}  // namespace app
