#include "replay/trajectory_reader.h"

#include <fstream>
#include <vector>

#include "replay/text_lines.h"
#include "replay/trajectory_formats.h"

namespace replay {
namespace {

constexpr std::string_view kSqliteMagic{"SQLite format 3\0", 16};

bool isSqlite(std::string_view content) { return content.substr(0, kSqliteMagic.size()) == kSqliteMagic; }

// A comma-separated line naming id, x and y (any case) is a CSV header.
bool isCsvHeader(std::string_view line) {
    std::vector<std::string_view> fields;
    splitCommas(line, fields);
    bool id = false, x = false, y = false;
    for (std::string_view field : fields) {
        const std::string name = lowercase(field);
        id = id || name == "id";
        x = x || name == "x";
        y = y || name == "y";
    }
    return id && x && y;
}

// The first line that is neither blank nor a comment decides; `comments` says whether "#" lines came
// before it (then it is PeTrack's, and its reader says what is wrong with a bad row).
Format detectFromLine(const TextLines& lines, std::string_view line, bool comments) {
    if (isCsvHeader(line)) return Format::Csv;
    if (comments) return Format::PeTrack;
    if (line.find(',') != std::string_view::npos)
        lines.fail("cannot tell the format: comma-separated, but no header naming id, x and y; give " +
                   std::string(kFormatFlag));
    std::vector<std::string_view> fields;
    splitWhitespace(line, fields);
    std::size_t numbers = 0;
    for (std::string_view field : fields) numbers += isNumber(field) ? 1 : 0;
    if (numbers == fields.size() && numbers == 8) return Format::Obsmat;
    if (numbers == fields.size() && (numbers == 4 || numbers == 5)) return Format::PeTrack;
    lines.fail("cannot tell the format from a line of " + std::to_string(fields.size()) + " fields (" +
               std::to_string(numbers) + " numbers; PeTrack rows have 4 or 5, ETH/UCY obsmat 8); give " +
               std::string(kFormatFlag));
}

// The first bytes, enough to see SQLite's magic without reading a large database as text.
std::string fileHead(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::string head(kSqliteMagic.size(), '\0');
    file.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(file.gcount()));
    return head;
}

}  // namespace

Format detectFormat(const std::string& path, std::string_view content) {
    if (isSqlite(content)) return Format::JuPedSim;
    TextLines lines(path, content);
    bool comments = false;
    std::string_view line;
    while (lines.next(line)) {
        line = trim(line);
        if (!line.empty() && line.front() == '#') comments = true;
        else if (!line.empty()) return detectFromLine(lines, line, comments);
    }
    return Format::PeTrack;
}

Recording readTrajectories(const std::string& path, const ReadOptions& options) {
    Format format = options.format;
    if (format == Format::JuPedSim || (format == Format::Auto && isSqlite(fileHead(path))))
        return readJuPedSim(path, options);
    const std::string text = readWholeFile(path);
    if (format == Format::Auto) format = detectFormat(path, text);
    switch (format) {
        case Format::Obsmat: return readObsmat(path, text, options);
        case Format::Csv: return readCsv(path, text, options);
        default: return readPeTrack(path, text, options);
    }
}

}  // namespace replay
