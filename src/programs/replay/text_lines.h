#pragma once
// The text formats' common ground: numbered lines, fields split by whitespace or commas, and numbers
// read from them strictly, every failure one line "PATH:LINE: problem" (app::Error), so that a user
// can open the file at the line that is wrong.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace replay {

// The whole file; throws "PATH: cannot open (reason)".
std::string readWholeFile(const std::string& path);

// A file's lines from the first, without line ends ("\n" or "\r\n"), numbered from 1.
class TextLines {
public:
    TextLines(std::string path, std::string_view text) : path_(std::move(path)), text_(text) {}
    // The next line, false at the end of the text.
    bool next(std::string_view& line);
    std::uint64_t number() const { return number_; }
    const std::string& path() const { return path_; }
    // "PATH:LINE: problem" for the line last returned.
    [[noreturn]] void fail(const std::string& problem) const;

private:
    std::string path_;
    std::string_view text_;
    std::size_t at_ = 0;
    std::uint64_t number_ = 0;
};

std::string_view trim(std::string_view text);  // without leading and trailing spaces and tabs
std::string lowercase(std::string_view text);

// Fields separated by runs of spaces and tabs (PeTrack, ETH/UCY).
void splitWhitespace(std::string_view line, std::vector<std::string_view>& fields);
// Fields separated by single commas, each trimmed and unquoted (CSV); ",," is an empty field.
void splitCommas(std::string_view line, std::vector<std::string_view>& fields);

// The whole field as a finite decimal number ("7.0000000e+00" is one), or nothing.
std::optional<double> finiteNumber(std::string_view field);
inline bool isNumber(std::string_view field) { return finiteNumber(field).has_value(); }

// Field `column` (from 1, as a user counts) named `name`: a finite number, or a whole one. Throws
// through `lines` naming the column: "PATH:LINE: x (column 3) 'abc' is not a number".
double numberField(const TextLines& lines, std::string_view field, std::size_t column, const char* name);
std::int64_t wholeField(const TextLines& lines, std::string_view field, std::size_t column, const char* name);

}  // namespace replay
