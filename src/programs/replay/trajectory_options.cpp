#include "replay/trajectory_options.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include "app/error.h"
#include "app/number_text.h"
#include "app/options.h"

namespace replay {
namespace {

// A whole-string decimal number; throws naming `flag` otherwise.
double parseDecimal(const char* flag, const std::string& text, double min, double max) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(value))
        throw app::Error(std::string(flag) + ": '" + text + "' is not a number");
    if (value < min || value > max)
        throw app::Error(std::string(flag) + ": " + text + " is outside " + app::formatNumber(min) + ".." +
                         app::formatNumber(max));
    return value;
}

}  // namespace

const char* formatName(Format format) {
    switch (format) {
        case Format::Auto: return "auto";
        case Format::PeTrack: return "petrack";
        case Format::JuPedSim: return "jupedsim";
        case Format::Obsmat: return "obsmat";
        case Format::Csv: return "csv";
    }
    return "?";
}

const char* unitsName(Units units) {
    switch (units) {
        case Units::Unset: return "";
        case Units::Metres: return "m";
        case Units::Centimetres: return "cm";
        case Units::Millimetres: return "mm";
    }
    return "?";
}

double unitsPerMetre(Units units) {
    switch (units) {
        case Units::Centimetres: return 100.0;
        case Units::Millimetres: return 1000.0;
        default: return 1.0;
    }
}

Format parseTrajectoryFormat(const std::string& text) {
    for (Format f : {Format::Auto, Format::PeTrack, Format::JuPedSim, Format::Obsmat, Format::Csv})
        if (text == formatName(f)) return f;
    throw app::Error(std::string(kFormatFlag) + ": '" + text + "' is not auto, petrack, jupedsim, obsmat or csv");
}

double parseTrajectoryFps(const std::string& text) {
    const double fps = parseDecimal(kFpsFlag, text, 0.0, 100000.0);
    if (!(fps > 0.0)) throw app::Error(std::string(kFpsFlag) + ": the rate must be above 0 frames per second");
    return fps;
}

Units parseTrajectoryUnits(const std::string& text) {
    for (Units u : {Units::Metres, Units::Centimetres, Units::Millimetres})
        if (text == unitsName(u)) return u;
    throw app::Error(std::string(kUnitsFlag) + ": '" + text + "' is not m, cm or mm");
}

std::uint32_t parseTrajectoryCopies(const std::string& text) {
    return app::parseCount(kCopiesFlag, text, 1, kMaxCopies);
}

double parseTrajectorySmoothing(const std::string& text) {
    return parseDecimal(kSmoothingFlag, text, 0.0, kMaxSmoothingSeconds);
}

}  // namespace replay
