// PeTrack's text export, as the Jülich archive publishes it. The comments carry the rate and the
// column line's "/cm" suffixes the unit; files that lost them (only "#id frame x y z") need both from
// the user, since a corridor read in metres instead of centimetres is 100 times too large but
// otherwise plausible.
#include <algorithm>
#include <array>
#include <vector>

#include "app/number_text.h"
#include "replay/text_lines.h"
#include "replay/track_assembly.h"
#include "replay/trajectory_formats.h"

namespace replay {
namespace {

// Which field (from 0) holds each value; PeTrack writes "id frame x y z" unless its column line says otherwise.
struct Columns {
    enum { Id, Frame, X, Y, Count };
    std::array<std::size_t, Count> at{0, 1, 2, 3};
    Units units = Units::Unset;
    std::size_t needed() const { return *std::max_element(at.begin(), at.end()) + 1; }
};

constexpr const char* kColumnNames[Columns::Count] = {"id", "frame", "x", "y"};

// A comment is the column line when it names both id and frame ("# id frame x/cm y/cm z/cm"), not
// when it is prose that happens to start with "id".
bool isColumnLine(const std::vector<std::string_view>& words) {
    bool id = false, frame = false;
    for (std::string_view word : words) {
        const std::string name = lowercase(word.substr(0, word.find('/')));
        id = id || name == "id";
        frame = frame || name == "frame";
    }
    return id && frame;
}

Units unitFromSuffix(const TextLines& lines, std::string_view suffix, std::string_view column) {
    const std::string unit = lowercase(suffix);
    for (Units u : {Units::Metres, Units::Centimetres, Units::Millimetres})
        if (unit == unitsName(u)) return u;
    lines.fail("column '" + std::string(column) + "' has unit '" + std::string(suffix) + "', not m, cm or mm");
}

// "id frame x/cm y/cm z/cm": the position of each value and the unit of x and y.
Columns parseColumnLine(const TextLines& lines, const std::vector<std::string_view>& names) {
    Columns columns;
    std::array<bool, Columns::Count> found{};
    std::array<Units, Columns::Count> units{};
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::size_t slash = names[i].find('/');
        const std::string name = lowercase(names[i].substr(0, slash));
        for (int c = 0; c < Columns::Count; ++c)
            if (name == kColumnNames[c] && !found[c]) {
                found[c] = true;
                columns.at[c] = i;
                if (slash != std::string_view::npos) units[c] = unitFromSuffix(lines, names[i].substr(slash + 1), names[i]);
            }
    }
    for (int c = 0; c < Columns::Count; ++c)
        if (!found[c]) lines.fail(std::string("the column line names no ") + kColumnNames[c] + " column");
    if (units[Columns::X] != units[Columns::Y])
        lines.fail(std::string("x is in '") + unitsName(units[Columns::X]) + "' but y in '" + unitsName(units[Columns::Y]) + "'");
    columns.units = units[Columns::X];
    return columns;
}

// "# framerate: 25 fps".
double parseFramerate(const TextLines& lines, std::string_view comment) {
    const std::size_t colon = comment.find(':');
    std::vector<std::string_view> words;
    splitWhitespace(colon == std::string_view::npos ? std::string_view() : comment.substr(colon + 1), words);
    if (words.empty() || !isNumber(words[0])) lines.fail("the framerate line gives no number of frames per second");
    const double fps = numberField(lines, words[0], 1, "framerate");
    if (!(fps > 0.0)) lines.fail("framerate " + app::formatNumber(fps) + " is not above 0");
    return fps;
}

// "frame id x y" when the column line reorders them: what a short row lacks.
std::string columnList(const Columns& columns) {
    std::vector<std::pair<std::size_t, const char*>> order;
    for (int c = 0; c < Columns::Count; ++c) order.push_back({columns.at[c], kColumnNames[c]});
    std::sort(order.begin(), order.end());
    std::string list;
    for (const auto& [at, name] : order) {
        if (!list.empty()) list += ' ';
        list += name;
    }
    return list;
}

// One row's values from its fields, at the columns' positions (counted from 1 in messages).
Row readRow(const TextLines& lines, const std::vector<std::string_view>& fields, const Columns& columns) {
    if (fields.size() < columns.needed())
        lines.fail(std::to_string(fields.size()) + " columns where " + std::to_string(columns.needed()) +
                   " are needed (" + columnList(columns) + ")");
    const auto field = [&](int c) { return fields[columns.at[c]]; };
    const auto column = [&](int c) { return columns.at[c] + 1; };
    Row row;
    row.id = wholeField(lines, field(Columns::Id), column(Columns::Id), "id");
    row.when = static_cast<double>(wholeField(lines, field(Columns::Frame), column(Columns::Frame), "frame"));
    row.x = numberField(lines, field(Columns::X), column(Columns::X), "x");
    row.y = numberField(lines, field(Columns::Y), column(Columns::Y), "y");
    row.where = lines.number();
    return row;
}

}  // namespace

Recording readPeTrack(const std::string& path, std::string_view text, const ReadOptions& options) {
    TextLines lines(path, text);
    Columns columns;
    double fileFps = 0.0;
    std::vector<Row> rows;
    std::vector<std::string_view> fields;
    std::string_view line;
    while (lines.next(line)) {
        line = trim(line);
        if (line.empty()) continue;
        if (line.front() == '#') {
            const std::string_view comment = trim(line.substr(1));
            splitWhitespace(comment, fields);
            if (lowercase(comment).rfind("framerate", 0) == 0) fileFps = parseFramerate(lines, comment);
            else if (isColumnLine(fields)) columns = parseColumnLine(lines, fields);
            continue;
        }
        splitWhitespace(line, fields);
        rows.push_back(readRow(lines, fields, columns));
    }
    sortRows(rows, lineLocator(path), "frame", "line");
    const bool needed = !rows.empty();
    const Rate rate = chooseRate(path, options, fileFps, Provenance::File, "no '# framerate: N fps' line", needed);
    const Unit unit = chooseUnits(path, options, columns.units, Provenance::File,
                                  "no unit in a column line such as '# id frame x/cm y/cm'", needed);
    return makeRecording(path, Format::PeTrack, rows, rate, unit);
}

}  // namespace replay
