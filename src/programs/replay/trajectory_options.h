#pragma once
// How to read a trajectory file when the file does not say everything: its format (found from the
// content unless given), its frame rate and its length unit. The flags' names are fixed here so the
// readers' errors can tell the user which flag supplies what a file lacks.
#include <cstdint>
#include <string>

namespace replay {

enum class Format { Auto, PeTrack, JuPedSim, Obsmat, Csv };
enum class Units { Unset, Metres, Centimetres, Millimetres };

inline constexpr const char* kFormatFlag = "--trajectory-format";
inline constexpr const char* kFpsFlag = "--trajectory-fps";
inline constexpr const char* kUnitsFlag = "--trajectory-units";
inline constexpr const char* kCopiesFlag = "--trajectory-copies";
inline constexpr const char* kSmoothingFlag = "--trajectory-smoothing";

struct ReadOptions {
    Format format = Format::Auto;
    double fps = 0.0;             // frames per second; 0 = the file's (or inferred for ETH/UCY)
    Units units = Units::Unset;   // Unset = the file's (PeTrack's column line) or the format's metres
};

const char* formatName(Format format);  // "auto", "petrack", "jupedsim", "obsmat", "csv"
const char* unitsName(Units units);     // "", "m", "cm", "mm"
double unitsPerMetre(Units units);      // 1, 100, 1000 (Unset: 1)

// Flag values; each throws app::Error with one line naming its flag.
Format parseTrajectoryFormat(const std::string& text);  // auto, petrack, jupedsim, obsmat, csv
double parseTrajectoryFps(const std::string& text);     // a number above 0, at most 100,000
Units parseTrajectoryUnits(const std::string& text);    // m, cm, mm
std::uint32_t parseTrajectoryCopies(const std::string& text);  // 1..kMaxCopies
double parseTrajectorySmoothing(const std::string& text);      // seconds, 0 (off)..kMaxSmoothingSeconds

// 1,000,000 people are 2,084 copies of the 480-person corridor; the bound stops a typo before the
// placements alone (32 bytes a track) fill memory.
inline constexpr std::uint32_t kMaxCopies = 1u << 20;
// Beyond a few seconds smoothing no longer removes sway but cuts corners.
inline constexpr double kMaxSmoothingSeconds = 10.0;

}  // namespace replay
