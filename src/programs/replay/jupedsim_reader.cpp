// JuPedSim's trajectory output, a SQLite database (format version 2): positions in metres in
// trajectory_data(frame, id, pos_x, pos_y, ...), the rate in metadata(key, value) as 'fps'. Opened
// read-only: a replay never writes a user's file.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <sqlite3.h>

#include "app/error.h"
#include "replay/text_lines.h"
#include "replay/track_assembly.h"
#include "replay/trajectory_formats.h"

namespace replay {
namespace {

struct CloseDatabase {
    void operator()(sqlite3* db) const { sqlite3_close(db); }
};
struct FinalizeStatement {
    void operator()(sqlite3_stmt* statement) const { sqlite3_finalize(statement); }
};
using Database = std::unique_ptr<sqlite3, CloseDatabase>;
using Statement = std::unique_ptr<sqlite3_stmt, FinalizeStatement>;

Database open(const std::string& path) {
    sqlite3* db = nullptr;
    const int result = sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
    Database owned(db);
    if (result != SQLITE_OK)
        throw app::Error(path + ": cannot open as SQLite (" + (db ? sqlite3_errmsg(db) : sqlite3_errstr(result)) + ")");
    return owned;
}

// A prepared query, or null with SQLite's reason in `why` (a missing table or column).
Statement prepare(sqlite3* db, const char* sql, std::string& why) {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db, sql, -1, &statement, nullptr) != SQLITE_OK) why = sqlite3_errmsg(db);
    return Statement(statement);
}

std::string rowPlace(const std::string& path, std::uint64_t rowid) {
    return path + ": trajectory_data rowid " + std::to_string(rowid);
}

// Column `column` of the current row as a finite number (SQLite's REAL or INTEGER, not NULL or text).
double numberColumn(const std::string& path, sqlite3_stmt* statement, int column, std::uint64_t rowid) {
    const int type = sqlite3_column_type(statement, column);
    const char* name = sqlite3_column_name(statement, column);
    if (type != SQLITE_INTEGER && type != SQLITE_FLOAT) {
        const char* text = reinterpret_cast<const char*>(sqlite3_column_text(statement, column));
        throw app::Error(rowPlace(path, rowid) + ": " + name + " '" + (text ? text : "NULL") + "' is not a number");
    }
    const double value = sqlite3_column_double(statement, column);
    if (!std::isfinite(value)) throw app::Error(rowPlace(path, rowid) + ": " + name + " is not a finite number");
    return value;
}

std::int64_t wholeColumn(const std::string& path, sqlite3_stmt* statement, int column, std::uint64_t rowid) {
    const double value = numberColumn(path, statement, column, rowid);
    if (value != std::floor(value))
        throw app::Error(rowPlace(path, rowid) + ": " + sqlite3_column_name(statement, column) + " is not a whole number");
    return static_cast<std::int64_t>(value);
}

std::vector<Row> readRows(const std::string& path, sqlite3* db) {
    std::string why;
    const Statement query = prepare(db, "SELECT rowid, frame, id, pos_x, pos_y FROM trajectory_data", why);
    if (!query) throw app::Error(path + ": no table trajectory_data(frame, id, pos_x, pos_y) (" + why + ")");
    std::vector<Row> rows;
    int step = SQLITE_ROW;
    while ((step = sqlite3_step(query.get())) == SQLITE_ROW) {
        Row row;
        row.where = static_cast<std::uint64_t>(sqlite3_column_int64(query.get(), 0));
        row.when = static_cast<double>(wholeColumn(path, query.get(), 1, row.where));
        row.id = wholeColumn(path, query.get(), 2, row.where);
        row.x = numberColumn(path, query.get(), 3, row.where);
        row.y = numberColumn(path, query.get(), 4, row.where);
        rows.push_back(row);
    }
    if (step != SQLITE_DONE) throw app::Error(path + ": cannot read trajectory_data (" + sqlite3_errmsg(db) + ")");
    return rows;
}

// metadata's fps, 0 when the table or the key is missing.
double metadataFps(const std::string& path, sqlite3* db) {
    std::string why;
    const Statement query = prepare(db, "SELECT value FROM metadata WHERE key = 'fps'", why);
    if (!query || sqlite3_step(query.get()) != SQLITE_ROW) return 0.0;
    const char* text = reinterpret_cast<const char*>(sqlite3_column_text(query.get(), 0));
    const std::string value = text ? text : "NULL";
    const std::optional<double> fps = finiteNumber(value);
    if (!fps || !(*fps > 0.0)) throw app::Error(path + ": metadata fps '" + value + "' is not a number of frames per second");
    return *fps;
}

}  // namespace

Recording readJuPedSim(const std::string& path, const ReadOptions& options) {
    const Database db = open(path);
    std::vector<Row> rows = readRows(path, db.get());
    sortRows(rows, [&](std::uint64_t where) { return rowPlace(path, where); }, "frame", "rowid");
    const bool needed = !rows.empty();
    const double fileFps = options.fps > 0.0 ? 0.0 : metadataFps(path, db.get());
    const Rate rate = chooseRate(path, options, fileFps, Provenance::File, "no fps in its metadata table", needed);
    const Unit unit = chooseUnits(path, options, Units::Metres, Provenance::Format, "", false);
    return makeRecording(path, Format::JuPedSim, rows, rate, unit);
}

}  // namespace replay
