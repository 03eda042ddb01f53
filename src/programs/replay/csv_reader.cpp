// CSV with a header, as PedPy's demo data and many simulators write it (e.g. "ID,Frame,x,y,v_x,v_y").
// Columns are found by name, in any case and order, and the others ignored. A time column (seconds)
// is used as is; frames need a rate, which CSV files do not carry, so the user gives it.
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "replay/text_lines.h"
#include "replay/track_assembly.h"
#include "replay/trajectory_formats.h"

namespace replay {
namespace {

struct Header {
    enum { Id, Frame, Time, X, Y, Count };
    std::array<std::optional<std::size_t>, Count> at;
    bool seconds() const { return at[Time].has_value(); }  // time is preferred: it needs no rate
    std::size_t when() const { return seconds() ? *at[Time] : *at[Frame]; }
};

constexpr const char* kHeaderNames[Header::Count] = {"id", "frame", "time", "x", "y"};

Header parseHeader(const TextLines& lines, const std::vector<std::string_view>& names) {
    Header header;
    for (std::size_t i = 0; i < names.size(); ++i)
        for (int c = 0; c < Header::Count; ++c)
            if (!header.at[c] && lowercase(names[i]) == kHeaderNames[c]) header.at[c] = i;
    for (int c : {Header::Id, Header::X, Header::Y})
        if (!header.at[c]) lines.fail(std::string("the header names no ") + kHeaderNames[c] + " column");
    if (!header.at[Header::Frame] && !header.at[Header::Time]) lines.fail("the header names no frame or time column");
    return header;
}

Row readRow(const TextLines& lines, const std::vector<std::string_view>& fields, const Header& header) {
    const std::size_t id = *header.at[Header::Id], when = header.when();
    const std::size_t x = *header.at[Header::X], y = *header.at[Header::Y];
    const std::size_t needed = std::max({id, when, x, y}) + 1;
    if (fields.size() < needed)
        lines.fail(std::to_string(fields.size()) + " columns where the header needs " + std::to_string(needed));
    Row row;
    row.id = wholeField(lines, fields[id], id + 1, "id");
    row.when = header.seconds() ? numberField(lines, fields[when], when + 1, "time")
                                : static_cast<double>(wholeField(lines, fields[when], when + 1, "frame"));
    row.x = numberField(lines, fields[x], x + 1, "x");
    row.y = numberField(lines, fields[y], y + 1, "y");
    row.where = lines.number();
    return row;
}

}  // namespace

Recording readCsv(const std::string& path, std::string_view text, const ReadOptions& options) {
    TextLines lines(path, text);
    std::optional<Header> header;
    std::vector<Row> rows;
    std::vector<std::string_view> fields;
    std::string_view line;
    while (lines.next(line)) {
        line = trim(line);
        if (line.empty() || line.front() == '#') continue;
        splitCommas(line, fields);
        if (!header) {
            header = parseHeader(lines, fields);
            continue;
        }
        rows.push_back(readRow(lines, fields, *header));
    }
    const bool seconds = header && header->seconds();
    sortRows(rows, lineLocator(path), seconds ? "time" : "frame", "line");
    const bool needed = !rows.empty();
    // Times in seconds need no rate: fps stays 0, from the file.
    const Rate rate = seconds ? Rate{0.0, Provenance::File}
                              : chooseRate(path, options, 0.0, Provenance::File, "frames but no rate (CSV has none)", needed);
    const Unit unit = chooseUnits(path, options, Units::Metres, Provenance::Format, "", false);
    return makeRecording(path, Format::Csv, rows, rate, unit);
}

}  // namespace replay
