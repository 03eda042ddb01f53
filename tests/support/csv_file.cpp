#include "support/csv_file.h"

#include <algorithm>
#include <fstream>

namespace test {

std::vector<std::string> readLines(const std::string& path) {
    std::ifstream file(path);
    std::vector<std::string> result;
    for (std::string line; std::getline(file, line);) result.push_back(line);
    return result;
}

std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.push_back(field), field.clear();
        else field += c;
    }
    fields.push_back(field);
    return fields;
}

std::string csvField(const std::vector<std::string>& lines, std::size_t row, const std::string& name) {
    const std::string missing = "<no " + name + ">";
    if (lines.empty() || row >= lines.size()) return missing;
    const std::vector<std::string> header = csvFields(lines.front()), fields = csvFields(lines[row]);
    const auto at = std::find(header.begin(), header.end(), name);
    const auto column = static_cast<std::size_t>(at - header.begin());
    return at == header.end() || column >= fields.size() ? missing : fields[column];
}

}  // namespace test
