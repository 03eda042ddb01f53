#pragma once
// The CSV files the programs write (crowd-bench's --csv, --frame-log, --palette), read back by tests.
#include <string>
#include <vector>

namespace test {

// The file's lines, without their line ends.
std::vector<std::string> readLines(const std::string& path);

// A line's fields, split on the commas outside double quotes; the quotes are dropped.
std::vector<std::string> csvFields(const std::string& line);

// The field of column `name` in line `row` of `lines` (line 0 is the header, 1 the first row);
// "<no NAME>" when the header or the row lacks it.
std::string csvField(const std::vector<std::string>& lines, std::size_t row, const std::string& name);

}  // namespace test
