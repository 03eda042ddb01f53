#include "replay/text_lines.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "app/error.h"

namespace replay {

std::string readWholeFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw app::Error(path + ": cannot open (" + std::strerror(errno) + ")");
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) throw app::Error(path + ": cannot read (" + std::strerror(errno) + ")");
    return std::move(text).str();
}

bool TextLines::next(std::string_view& line) {
    if (at_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', at_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at_ = end + 1;
    ++number_;
    return true;
}

void TextLines::fail(const std::string& problem) const {
    throw app::Error(path_ + ":" + std::to_string(number_) + ": " + problem);
}

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

// Loops, not find_first_not_of(" \t"): libstdc++ calls memchr per character for a set, a tenth of
// reading the 120,790-row corridor.
std::string_view trim(std::string_view text) {
    std::size_t first = 0, end = text.size();
    while (first < end && blank(text[first])) ++first;
    while (end > first && blank(text[end - 1])) --end;
    return text.substr(first, end - first);
}

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

void splitWhitespace(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t at = 0;
    while (true) {
        while (at < line.size() && blank(line[at])) ++at;
        if (at == line.size()) return;
        const std::size_t first = at;
        while (at < line.size() && !blank(line[at])) ++at;
        fields.push_back(line.substr(first, at - first));
    }
}

void splitCommas(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t at = 0;
    while (true) {
        std::size_t end = line.find(',', at);
        if (end == std::string_view::npos) end = line.size();
        std::string_view field = trim(line.substr(at, end - at));
        if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = field.substr(1, field.size() - 2);
        fields.push_back(field);
        if (end == line.size()) return;
        at = end + 1;
    }
}

namespace {

// from_chars takes no leading '+', which some writers put before positive numbers.
bool parseDouble(std::string_view field, double& value, bool& finite) {
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    const char* end = field.data() + field.size();
    const auto [ptr, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || ptr != end || error == std::errc::invalid_argument) return false;
    // Out of range (1e999) reads as not finite: it is no position or time a file means.
    finite = error == std::errc() && std::isfinite(value);
    return true;
}

std::string where(std::size_t column, const char* name) {
    return std::string(name) + " (column " + std::to_string(column) + ") '";
}

}  // namespace

std::optional<double> finiteNumber(std::string_view field) {
    double value = 0.0;
    bool finite = false;
    if (parseDouble(field, value, finite) && finite) return value;
    return std::nullopt;
}

double numberField(const TextLines& lines, std::string_view field, std::size_t column, const char* name) {
    double value = 0.0;
    bool finite = false;
    if (field.empty()) lines.fail(std::string(name) + " (column " + std::to_string(column) + ") is empty");
    if (!parseDouble(field, value, finite)) lines.fail(where(column, name) + std::string(field) + "' is not a number");
    if (!finite) lines.fail(where(column, name) + std::string(field) + "' is not a finite number");
    return value;
}

std::int64_t wholeField(const TextLines& lines, std::string_view field, std::size_t column, const char* name) {
    const double value = numberField(lines, field, column, name);
    // 2^53: beyond it a double no longer holds every whole number, and no file counts that far.
    if (value != std::floor(value) || std::fabs(value) > 9007199254740992.0)
        lines.fail(where(column, name) + std::string(field) + "' is not a whole number");
    return static_cast<std::int64_t>(value);
}

}  // namespace replay
