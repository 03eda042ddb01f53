// ETH/UCY's obsmat.txt (Pellegrini et al. 2009, Lerner et al. 2007): "frame id x z y vx vz vy" in
// metres with the ground in x and y (columns 3 and 5; z is height, 0). Its frames count video frames,
// and annotations fall every 0.4 s, every 10th frame of UCY's 25 fps videos but every 6th of seq_eth's
// 15 fps: no rate fits all, so the rate is the common step over 0.4 s unless the user gives it.
#include <vector>

#include "app/number_text.h"
#include "replay/text_lines.h"
#include "replay/track_assembly.h"
#include "replay/trajectory_formats.h"

namespace replay {

Recording readObsmat(const std::string& path, std::string_view text, const ReadOptions& options) {
    TextLines lines(path, text);
    std::vector<Row> rows;
    std::vector<std::string_view> fields;
    std::string_view line;
    while (lines.next(line)) {
        line = trim(line);
        if (line.empty() || line.front() == '#') continue;
        splitWhitespace(line, fields);
        if (fields.size() < 5) lines.fail(std::to_string(fields.size()) + " columns where 5 are needed (frame id x z y)");
        Row row;
        row.when = static_cast<double>(wholeField(lines, fields[0], 1, "frame"));
        row.id = wholeField(lines, fields[1], 2, "id");
        row.x = numberField(lines, fields[2], 3, "x");
        row.y = numberField(lines, fields[4], 5, "y");
        row.where = lines.number();
        rows.push_back(row);
    }
    sortRows(rows, lineLocator(path), "frame", "line");
    const double step = mostCommonStep(rows);
    const double inferred = step / kObsmatIntervalSeconds;
    const Rate rate = chooseRate(path, options, inferred, Provenance::Inferred,
                                 "no person has two frames to infer the rate from (one every " +
                                     app::formatNumber(kObsmatIntervalSeconds) + " s)",
                                 !rows.empty());
    const Unit unit = chooseUnits(path, options, Units::Metres, Provenance::Format, "", false);
    return makeRecording(path, Format::Obsmat, rows, rate, unit);
}

}  // namespace replay
