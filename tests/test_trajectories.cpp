// Reading pedestrian trajectory files (src/programs/replay/, docs/host-driven.md): each format from
// small files written here, with exact times and positions, unit and axis conversion, detection and its
// override, every malformed case with its exact "file:line" message, empty and one-person files, and
// the flags' values. Copies and the feed: test_trajectory_replay.cpp; the shared recordings:
// test_trajectory_recordings.cpp.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include "app/error.h"
#include "replay/trajectory_reader.h"

namespace {

using namespace replay;

// A folder of its own for each test's files, removed afterwards.
class TrajectoryFiles : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        dir_ = std::filesystem::temp_directory_path() /
               ("crowd-trajectories-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        const std::string path = (dir_ / name).string();
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    // A JuPedSim database from SQL statements.
    std::string database(const std::string& name, const std::string& sql) {
        const std::string path = (dir_ / name).string();
        sqlite3* db = nullptr;
        EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
        char* error = nullptr;
        EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << (error ? error : "");
        sqlite3_free(error);
        sqlite3_close(db);
        return path;
    }

    std::filesystem::path dir_;
};

// The message `read` fails with ("no error" when it does not).
std::string errorOf(const std::function<void()>& read) {
    try {
        read();
    } catch (const app::Error& error) {
        return error.what();
    }
    return "no error";
}

std::string readError(const std::string& path, const ReadOptions& options = {}) {
    return errorOf([&] { readTrajectories(path, options); });
}

void expectSample(const Sample& s, double time, double x, double z) {
    EXPECT_DOUBLE_EQ(s.time, time);
    EXPECT_DOUBLE_EQ(s.x, x);
    EXPECT_DOUBLE_EQ(s.z, z);
}

constexpr const char* kJuPedSimSchema =
    "CREATE TABLE trajectory_data (frame INTEGER NOT NULL, id INTEGER NOT NULL, pos_x REAL NOT NULL, "
    "pos_y REAL NOT NULL, ori_x REAL NOT NULL, ori_y REAL NOT NULL);"
    "CREATE TABLE metadata(key TEXT NOT NULL UNIQUE PRIMARY KEY, value TEXT NOT NULL);";

}  // namespace

// ---- PeTrack ----

TEST_F(TrajectoryFiles, PeTrackTakesRateAndUnitsFromItsCommentsAndMapsGroundToWorldXz) {
    const std::string path = write("corridor.txt",
                                   "# PeTrack project: bi_corr.pet\n"
                                   "# framerate: 25 fps\n"
                                   "# z: can be 3d position or height of person\n"
                                   "# id frame x/cm y/cm z/cm\n"
                                   "1 94 -554.56 309.452 176\n"
                                   "1 95 -548.555 310.541 176\n"
                                   "2 95 100 -200 170\n");
    const Recording r = readTrajectories(path);
    EXPECT_EQ(r.info.format, "petrack");
    EXPECT_EQ(r.info.fps, 25.0);
    EXPECT_EQ(r.info.fpsFrom, Provenance::File);
    EXPECT_EQ(r.info.units, "cm");
    EXPECT_EQ(r.info.unitsFrom, Provenance::File);
    EXPECT_EQ(r.info.people, 2u);
    EXPECT_EQ(r.info.rows, 3u);
    ASSERT_EQ(r.tracks.size(), 2u);
    EXPECT_EQ(r.tracks[0].id, 1);
    ASSERT_EQ(r.tracks[0].samples.size(), 2u);
    // Frame 94 at 25 fps is 3.76 s: the file's own clock, not restarted at 0. File y becomes -z.
    expectSample(r.tracks[0].samples[0], 3.76, -5.5456, -3.09452);
    expectSample(r.tracks[0].samples[1], 3.8, -5.48555, -3.10541);
    expectSample(r.tracks[1].samples[0], 3.8, 1.0, 2.0);
    EXPECT_DOUBLE_EQ(r.info.extent.minX, -5.5456);
    EXPECT_DOUBLE_EQ(r.info.extent.maxX, 1.0);
    EXPECT_DOUBLE_EQ(r.info.extent.minZ, -3.10541);
    EXPECT_DOUBLE_EQ(r.info.extent.maxZ, 2.0);
    EXPECT_DOUBLE_EQ(r.info.startTime, 3.76);
    EXPECT_DOUBLE_EQ(r.info.endTime, 3.8);
}

TEST_F(TrajectoryFiles, WorldAxesAreARotationNotAMirror) {
    // East, then north on the file's map (x east, y north): a left, counter-clockwise turn. Seen from
    // above (from +y, right-handed: x to the right, -z up the page) the world must show the same turn.
    const std::string path = write("turn.txt", "# framerate: 1 fps\n# id frame x/m y/m\n1 0 0 0\n1 1 1 0\n1 2 1 1\n");
    const Recording r = readTrajectories(path);
    const std::vector<Sample>& s = r.tracks[0].samples;
    const double ax = s[1].x - s[0].x, az = s[1].z - s[0].z, bx = s[2].x - s[1].x, bz = s[2].z - s[1].z;
    // On the page (right, up) = (x, -z) a counter-clockwise turn has a positive cross product.
    EXPECT_GT(az * bx - ax * bz, 0.0);
    expectSample(s[2], 2.0, 1.0, -1.0);
}

TEST_F(TrajectoryFiles, PeTrackReadsTabsMetresAndMillimetres) {
    const std::string metres = write("bottleneck.txt",
                                     "#This is an automatically generated trajectory file\n"
                                     "# framerate: 25 fps\n"
                                     "# id frame x/m y/m z/m\n"
                                     "1\t0\t2.1569\t2.659\t1.76\n"
                                     "1\t1\t2.1570\t2.658\t1.76\n");
    const Recording r = readTrajectories(metres);
    EXPECT_EQ(r.info.units, "m");
    expectSample(r.tracks[0].samples[1], 0.04, 2.157, -2.658);
    const std::string mm = write("mm.txt", "# framerate: 10 fps\n# id frame x/mm y/mm\n7 3 1500 -250\n");
    const Recording m = readTrajectories(mm);
    EXPECT_EQ(m.info.units, "mm");
    expectSample(m.tracks[0].samples[0], 0.3, 1.5, 0.25);
}

TEST_F(TrajectoryFiles, PeTrackColumnLineMayReorderColumns) {
    const std::string path = write("reordered.txt", "# framerate: 10 fps\n# frame id y/cm x/cm\n20 5 300 100\n");
    const Recording r = readTrajectories(path);
    EXPECT_EQ(r.tracks[0].id, 5);
    expectSample(r.tracks[0].samples[0], 2.0, 1.0, -3.0);
}

TEST_F(TrajectoryFiles, PeTrackWithoutRateOrUnitsNeedsTheFlags) {
    const std::string path = write("bare.txt", "#id frame x y z\n1 10 1 2 1.7\n1 11 2 2 1.7\n");
    EXPECT_EQ(readError(path), path + ": no '# framerate: N fps' line; give --trajectory-fps");
    EXPECT_EQ(readError(path, {.fps = 25.0}),
              path + ": no unit in a column line such as '# id frame x/cm y/cm'; give --trajectory-units");
    const Recording r = readTrajectories(path, {.fps = 25.0, .units = Units::Centimetres});
    EXPECT_EQ(r.info.fpsFrom, Provenance::Flag);
    EXPECT_EQ(r.info.unitsFrom, Provenance::Flag);
    expectSample(r.tracks[0].samples[1], 0.44, 0.02, -0.02);
    // No comments at all: 4 or 5 numbers a row is PeTrack too.
    const std::string noComments = write("rows.txt", "1 10 1 2\n");
    EXPECT_EQ(readError(noComments), noComments + ": no '# framerate: N fps' line; give --trajectory-fps");
}

TEST_F(TrajectoryFiles, FlagsOverrideWhatTheFileSays) {
    const std::string path = write("f.txt", "# framerate: 25 fps\n# id frame x/cm y/cm\n1 50 100 100\n");
    const Recording r = readTrajectories(path, {.fps = 50.0, .units = Units::Metres});
    EXPECT_EQ(r.info.fps, 50.0);
    EXPECT_EQ(r.info.fpsFrom, Provenance::Flag);
    EXPECT_EQ(r.info.units, "m");
    EXPECT_EQ(r.info.unitsFrom, Provenance::Flag);
    expectSample(r.tracks[0].samples[0], 1.0, 100.0, -100.0);
}

TEST_F(TrajectoryFiles, RowsOutOfOrderAreSortedByFramePerPerson) {
    const std::string path = write("shuffled.txt",
                                   "# framerate: 10 fps\n# id frame x/m y/m\n"
                                   "2 3 0 0\n1 2 2 0\n1 0 0 0\n2 1 5 0\n1 1 1 0\n");
    const Recording r = readTrajectories(path);
    ASSERT_EQ(r.tracks.size(), 2u);
    EXPECT_EQ(r.tracks[0].id, 1);  // ascending ids
    ASSERT_EQ(r.tracks[0].samples.size(), 3u);
    for (int i = 0; i < 3; ++i) expectSample(r.tracks[0].samples[i], 0.1 * i, i, 0.0);
    expectSample(r.tracks[1].samples[0], 0.1, 5.0, 0.0);
    expectSample(r.tracks[1].samples[1], 0.3, 0.0, 0.0);
}

// ---- ETH/UCY obsmat ----

TEST_F(TrajectoryFiles, ObsmatInfersTheRateFromFrameStepsOverFourTenthsOfASecond) {
    // UCY: every 10th frame of 25 fps video. Ground in columns 3 and 5, in scientific notation.
    const std::string ucy = write("obsmat.txt",
                                  "  1.0000000e+01   1.0000000e+00   8.4560000e+00   0.0000000e+00   3.5000000e+00   1.0e+00   0.0e+00   0.0e+00\n"
                                  "  2.0000000e+01   1.0000000e+00   8.8560000e+00   0.0000000e+00   3.5000000e+00   1.0e+00   0.0e+00   0.0e+00\n"
                                  "  3.0000000e+01   1.0000000e+00   9.2560000e+00   0.0000000e+00   3.5000000e+00   1.0e+00   0.0e+00   0.0e+00\n"
                                  "  2.0000000e+01   2.0000000e+00  -1.0000000e+00   0.0000000e+00   2.0000000e+00   1.0e+00   0.0e+00   0.0e+00\n");
    const Recording r = readTrajectories(ucy);
    EXPECT_EQ(r.info.format, "obsmat");
    EXPECT_EQ(r.info.fps, 25.0);
    EXPECT_EQ(r.info.fpsFrom, Provenance::Inferred);
    EXPECT_EQ(r.info.units, "m");
    EXPECT_EQ(r.info.unitsFrom, Provenance::Format);
    expectSample(r.tracks[0].samples[0], 0.4, 8.456, -3.5);
    expectSample(r.tracks[0].samples[2], 1.2, 9.256, -3.5);
    expectSample(r.tracks[1].samples[0], 0.8, -1.0, -2.0);
    // ETH's seq_eth: every 6th frame of 15 fps video.
    const std::string eth = write("eth.txt", "6 1 0 0 0 0 0 0\n12 1 1 0 0 0 0 0\n18 1 2 0 0 0 0 0\n");
    const Recording e = readTrajectories(eth);
    EXPECT_EQ(e.info.fps, 15.0);
    expectSample(e.tracks[0].samples[2], 1.2, 2.0, -0.0);
    const Recording flagged = readTrajectories(eth, {.fps = 30.0});
    EXPECT_EQ(flagged.info.fpsFrom, Provenance::Flag);
    expectSample(flagged.tracks[0].samples[2], 0.6, 2.0, 0.0);
}

TEST_F(TrajectoryFiles, ObsmatOfSingleRowsCannotInferItsRate) {
    const std::string path = write("single.txt", "10 1 0 0 0 0 0 0\n10 2 1 0 0 0 0 0\n");
    EXPECT_EQ(readError(path), path + ": no person has two frames to infer the rate from (one every 0.4 s); give --trajectory-fps");
    EXPECT_EQ(readTrajectories(path, {.fps = 25.0}).info.people, 2u);
}

// ---- CSV ----

TEST_F(TrajectoryFiles, CsvFindsItsColumnsByNameInAnyCase) {
    const std::string path = write("single-file.csv",
                                   "ID,Frame,x,y,v_x,v_y\n"
                                   "12,1010,-0.9,-0.1,-0.18,-0.14\n"
                                   "13,1010,-0.3,-0.08,-0.13,-0.08\n"
                                   "13,1020,-0.4,-0.08,-0.16,0.08\n");
    EXPECT_EQ(readError(path), path + ": frames but no rate (CSV has none); give --trajectory-fps");
    const Recording r = readTrajectories(path, {.fps = 25.0});
    EXPECT_EQ(r.info.format, "csv");
    EXPECT_EQ(r.info.fpsFrom, Provenance::Flag);
    EXPECT_EQ(r.info.unitsFrom, Provenance::Format);
    ASSERT_EQ(r.tracks.size(), 2u);
    expectSample(r.tracks[1].samples[1], 40.8, -0.4, 0.08);
}

TEST_F(TrajectoryFiles, CsvTimeColumnIsSecondsAndNeedsNoRate) {
    const std::string path = write("timed.csv", "x, Y ,TIME,id\n1.5,2,0.25,4\n\"3\",4,0.75,4\r\n");
    const Recording r = readTrajectories(path, {.units = Units::Centimetres});
    EXPECT_EQ(r.info.fps, 0.0);
    EXPECT_EQ(r.info.fpsFrom, Provenance::File);
    EXPECT_EQ(r.info.units, "cm");
    expectSample(r.tracks[0].samples[0], 0.25, 0.015, -0.02);
    expectSample(r.tracks[0].samples[1], 0.75, 0.03, -0.04);
}

// ---- JuPedSim ----

TEST_F(TrajectoryFiles, JuPedSimReadsItsDatabaseAndMetadataRate) {
    const std::string path = database("sim.sqlite", std::string(kJuPedSimSchema) +
                                                        "INSERT INTO metadata VALUES ('version', '2'), ('fps', '25.0');"
                                                        "INSERT INTO trajectory_data VALUES (1, 3, 1.5, 2.5, 0, 0), "
                                                        "(0, 3, 1.0, 2.0, 0, 0), (0, 1, -4.0, 8.25, 0, 0);");
    const Recording r = readTrajectories(path);
    EXPECT_EQ(r.info.format, "jupedsim");
    EXPECT_EQ(r.info.fps, 25.0);
    EXPECT_EQ(r.info.fpsFrom, Provenance::File);
    EXPECT_EQ(r.info.units, "m");
    ASSERT_EQ(r.tracks.size(), 2u);
    EXPECT_EQ(r.tracks[0].id, 1);
    expectSample(r.tracks[0].samples[0], 0.0, -4.0, -8.25);
    expectSample(r.tracks[1].samples[1], 0.04, 1.5, -2.5);
}

TEST_F(TrajectoryFiles, JuPedSimErrorsNameTheDatabaseRow) {
    const std::string noFps =
        database("nofps.sqlite", std::string(kJuPedSimSchema) + "INSERT INTO trajectory_data VALUES (0, 1, 0, 0, 0, 0);");
    EXPECT_EQ(readError(noFps), noFps + ": no fps in its metadata table; give --trajectory-fps");
    EXPECT_EQ(readTrajectories(noFps, {.fps = 10.0}).info.fpsFrom, Provenance::Flag);
    const std::string twice = database("twice.sqlite", std::string(kJuPedSimSchema) +
                                                           "INSERT INTO metadata VALUES ('fps', '25');"
                                                           "INSERT INTO trajectory_data VALUES (0, 1, 0, 0, 0, 0), "
                                                           "(1, 1, 0, 0, 0, 0), (0, 1, 1, 1, 0, 0);");
    EXPECT_EQ(readError(twice), twice + ": trajectory_data rowid 3: person 1 has frame 0 twice (also at rowid 1)");
    const std::string text = database("text.sqlite", "CREATE TABLE trajectory_data (frame, id, pos_x, pos_y);"
                                                     "INSERT INTO trajectory_data VALUES (0, 1, 0, 0), (1, 1, 'far', 0);");
    EXPECT_EQ(readError(text, {.fps = 25.0}), text + ": trajectory_data rowid 2: pos_x 'far' is not a number");
    const std::string none = database("none.sqlite", "CREATE TABLE other (a);");
    EXPECT_EQ(readError(none),
              none + ": no table trajectory_data(frame, id, pos_x, pos_y) (no such table: trajectory_data)");
    const std::string badFps = database("badfps.sqlite", std::string(kJuPedSimSchema) +
                                                             "INSERT INTO metadata VALUES ('fps', 'fast');"
                                                             "INSERT INTO trajectory_data VALUES (0, 1, 0, 0, 0, 0);");
    EXPECT_EQ(readError(badFps), badFps + ": metadata fps 'fast' is not a number of frames per second");
}

// ---- Detection ----

TEST_F(TrajectoryFiles, FormatIsFoundFromTheContentNotTheName) {
    const std::string sqlite = database("a.txt", std::string(kJuPedSimSchema) + "INSERT INTO metadata VALUES ('fps', '25');");
    const std::string csv = write("b.sqlite", "id,frame,x,y\n1,0,0,0\n");
    const std::string petrack = write("c.csv", "# comment\n");
    const std::string obsmat = write("d.txt", "1 1 0 0 0 0 0 0\n");
    const std::string rows = write("e.txt", "1 1 0 0 1.8\n");
    EXPECT_EQ(readTrajectories(sqlite).info.format, "jupedsim");
    EXPECT_EQ(readTrajectories(csv, {.fps = 25.0}).info.format, "csv");
    EXPECT_EQ(readTrajectories(petrack).info.format, "petrack");
    EXPECT_EQ(readTrajectories(obsmat, {.fps = 25.0}).info.format, "obsmat");
    EXPECT_EQ(detectFormat(rows, "1 1 0 0 1.8\n"), Format::PeTrack);
    EXPECT_EQ(detectFormat("x", "\n  \n\tID , X,Y,frame\n"), Format::Csv);
    EXPECT_EQ(detectFormat("x", std::string_view("SQLite format 3\0rest", 20)), Format::JuPedSim);
    EXPECT_EQ(detectFormat("x", "# a PeTrack file\n1 1 0 0 0 0 0 0\n"), Format::PeTrack);  // comments first
    EXPECT_EQ(detectFormat("x", "# people walking\nid,frame,x,y\n"), Format::Csv);
}

TEST_F(TrajectoryFiles, AnExplicitFormatOverridesDetection) {
    // 8 numbers a row looks like obsmat (frame id x z y ...); as PeTrack it is id frame x y.
    const std::string path = write("eight.txt", "1 10 2 3 4 0 0 0\n");
    const Recording asObsmat = readTrajectories(path, {.fps = 25.0});
    expectSample(asObsmat.tracks[0].samples[0], 0.04, 2.0, -4.0);
    const Recording asPeTrack = readTrajectories(path, {.format = Format::PeTrack, .fps = 25.0, .units = Units::Metres});
    EXPECT_EQ(asPeTrack.info.format, "petrack");
    EXPECT_EQ(asPeTrack.tracks[0].id, 1);
    expectSample(asPeTrack.tracks[0].samples[0], 0.4, 2.0, -3.0);
}

TEST_F(TrajectoryFiles, UnknownContentAsksForTheFormat) {
    const std::string words = write("words.txt", "\nhello there\n");
    EXPECT_EQ(readError(words), words + ":2: cannot tell the format from a line of 2 fields (0 numbers; PeTrack rows "
                                        "have 4 or 5, ETH/UCY obsmat 8); give --trajectory-format");
    const std::string commas = write("commas.csv", "a,b,c\n");
    EXPECT_EQ(readError(commas),
              commas + ":1: cannot tell the format: comma-separated, but no header naming id, x and y; give --trajectory-format");
}

// ---- Malformed content: one line each, at the line that is wrong ----

TEST_F(TrajectoryFiles, MalformedRowsAreRefusedAtTheirLine) {
    const std::string head = "# framerate: 25 fps\n# id frame x/m y/m z/m\n";
    const std::map<std::string, std::string> cases = {
        {"1 94 abc 3\n", ":3: x (column 3) 'abc' is not a number"},
        {"1 94 3\n", ":3: 3 columns where 4 are needed (id frame x y)"},
        {"1 94 nan 3\n", ":3: x (column 3) 'nan' is not a finite number"},
        {"1 94 1 inf\n", ":3: y (column 4) 'inf' is not a finite number"},
        {"1 94 1 1e999\n", ":3: y (column 4) '1e999' is not a finite number"},
        {"1 94.5 1 1\n", ":3: frame (column 2) '94.5' is not a whole number"},
        {"x 94 1 1\n", ":3: id (column 1) 'x' is not a number"},
        {"1 94 1 1 1.7\n1 95 1 1 1.7\n\n1 94 2 2 1.7\n", ":6: person 1 has frame 94 twice (also at line 3)"},
    };
    for (const auto& [rows, message] : cases) {
        const std::string path = write("bad.txt", head + rows);
        EXPECT_EQ(readError(path), path + message) << rows;
    }
}

TEST_F(TrajectoryFiles, MalformedHeadersAreRefusedAtTheirLine) {
    const std::string noY = write("noy.txt", "# framerate: 25 fps\n# id frame x/cm z/cm\n1 1 1 1\n");
    EXPECT_EQ(readError(noY), noY + ":2: the column line names no y column");
    const std::string feet = write("feet.txt", "# id frame x/ft y/ft\n");
    EXPECT_EQ(readError(feet), feet + ":1: column 'x/ft' has unit 'ft', not m, cm or mm");
    const std::string mixed = write("mixed.txt", "# id frame x/m y/cm\n");
    EXPECT_EQ(readError(mixed), mixed + ":1: x is in 'm' but y in 'cm'");
    const std::string rate = write("rate.txt", "# framerate: fast\n");
    EXPECT_EQ(readError(rate), rate + ":1: the framerate line gives no number of frames per second");
    const std::string zero = write("zero.txt", "# framerate: 0 fps\n");
    EXPECT_EQ(readError(zero), zero + ":1: framerate 0 is not above 0");
    const std::string csvNoX = write("nox.csv", "id,frame,y\n1,1,1\n");
    EXPECT_EQ(readError(csvNoX, {.format = Format::Csv}), csvNoX + ":1: the header names no x column");
    const std::string csvNoTime = write("notime.csv", "# people\nid,x,y\n");
    EXPECT_EQ(readError(csvNoTime), csvNoTime + ":2: the header names no frame or time column");
    const std::string csvShort = write("short.csv", "id,frame,x,y\n1,2,3\n");
    EXPECT_EQ(readError(csvShort, {.fps = 25.0}), csvShort + ":2: 3 columns where the header needs 4");
    const std::string csvEmpty = write("emptyfield.csv", "id,frame,x,y\n1,2,,3\n");
    EXPECT_EQ(readError(csvEmpty, {.fps = 25.0}), csvEmpty + ":2: x (column 3) is empty");
    const std::string obsShort = write("obs.txt", "1 1 0 0 0 0 0 0\n1 2 0 0\n");
    EXPECT_EQ(readError(obsShort, {.fps = 25.0}), obsShort + ":2: 4 columns where 5 are needed (frame id x z y)");
    const std::string missing = (dir_ / "missing.txt").string();
    EXPECT_EQ(readError(missing), missing + ": cannot open (No such file or directory)");
}

TEST_F(TrajectoryFiles, EmptyAndCommentOnlyFilesAreEmptyRecordings) {
    for (const std::string& text : {std::string(), std::string("\n\n"), std::string("# framerate: 25 fps\n# id frame x y z\n")}) {
        const Recording r = readTrajectories(write("empty.txt", text));  // no rate or unit needed: no rows
        EXPECT_EQ(r.info.people, 0u);
        EXPECT_EQ(r.info.rows, 0u);
        EXPECT_TRUE(r.tracks.empty());
        EXPECT_TRUE(r.info.extent.empty());
    }
    EXPECT_EQ(readTrajectories(write("header.csv", "id,frame,x,y\n")).info.people, 0u);
    EXPECT_EQ(readTrajectories(write("empty.csv", ""), {.format = Format::Csv}).info.people, 0u);
    EXPECT_EQ(readTrajectories(database("empty.sqlite", kJuPedSimSchema)).info.people, 0u);
}

TEST_F(TrajectoryFiles, OnePersonOneRowIsARecording) {
    const Recording r = readTrajectories(write("one.txt", "# framerate: 25 fps\n# id frame x/m y/m\n42 0 1 2\n"));
    ASSERT_EQ(r.tracks.size(), 1u);
    EXPECT_EQ(r.tracks[0].id, 42);
    EXPECT_EQ(r.info.duration(), 0.0);
    EXPECT_EQ(r.info.extent.width(), 0.0);
}

// ---- Flag values ----

TEST(TrajectoryOptions, FlagValuesParseOrNameTheirFlag) {
    EXPECT_EQ(parseTrajectoryFormat("obsmat"), Format::Obsmat);
    EXPECT_EQ(parseTrajectoryFormat("auto"), Format::Auto);
    EXPECT_EQ(parseTrajectoryFps("12.5"), 12.5);
    EXPECT_EQ(parseTrajectoryUnits("mm"), Units::Millimetres);
    EXPECT_EQ(parseTrajectoryCopies("2084"), 2084u);
    EXPECT_EQ(parseTrajectorySmoothing("0"), 0.0);
    EXPECT_EQ(errorOf([] { parseTrajectoryFormat("xml"); }),
              "--trajectory-format: 'xml' is not auto, petrack, jupedsim, obsmat or csv");
    EXPECT_EQ(errorOf([] { parseTrajectoryFps("fast"); }), "--trajectory-fps: 'fast' is not a number");
    EXPECT_EQ(errorOf([] { parseTrajectoryFps("0"); }), "--trajectory-fps: the rate must be above 0 frames per second");
    EXPECT_EQ(errorOf([] { parseTrajectoryUnits("ft"); }), "--trajectory-units: 'ft' is not m, cm or mm");
    EXPECT_EQ(errorOf([] { parseTrajectoryCopies("0"); }), "--trajectory-copies: 0 is too small (at least 1)");
    EXPECT_EQ(errorOf([] { parseTrajectorySmoothing("-1"); }), "--trajectory-smoothing: -1 is outside 0..10");
}
