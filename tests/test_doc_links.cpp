// README.md and docs/*.md: every relative link names a file or folder that exists, and every #anchor
// names a heading of the Markdown file it points into, as GitHub derives anchors from headings. Also:
// the README's test command is the one .ci/run runs.
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

const fs::path kSource = CROWD_SOURCE_DIR;

std::vector<std::string> readLines(const fs::path& path) {
    std::ifstream file(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);) lines.push_back(line);
    return lines;
}

bool isFence(const std::string& line) { return line.rfind("```", 0) == 0; }

// GitHub's anchor for a heading: lower case, spaces to '-', letters, digits, '-' and '_' kept, every
// other ASCII character dropped. Non-ASCII characters are dropped too (GitHub keeps non-ASCII letters:
// a heading with one would need this to learn Unicode); a repeated heading gets -1, -2, ...
std::string slug(const std::string& heading) {
    std::string out;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 'A' && u <= 'Z') out += static_cast<char>(u - 'A' + 'a');
        else if ((u >= 'a' && u <= 'z') || (u >= '0' && u <= '9') || c == '-' || c == '_') out += c;
        else if (c == ' ') out += '-';
    }
    return out;
}

std::set<std::string> anchorsOf(const fs::path& markdown) {
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    bool fence = false;
    for (const std::string& line : readLines(markdown)) {
        if (isFence(line)) fence = !fence;
        if (fence) continue;
        const std::size_t level = line.find_first_not_of('#');
        if (level == 0 || level == std::string::npos || level > 6 || line[level] != ' ') continue;
        std::string text = line.substr(level + 1);
        while (!text.empty() && (text.back() == ' ' || text.back() == '#')) text.pop_back();
        const std::string base = slug(text);
        const int n = seen[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
    }
    return anchors;
}

struct Link {
    int line;
    std::string target;
};

// Every inline link or image target outside fenced blocks and code spans.
std::vector<Link> linksOf(const fs::path& markdown) {
    std::vector<Link> links;
    bool fence = false;
    int number = 0;
    for (const std::string& raw : readLines(markdown)) {
        ++number;
        if (isFence(raw)) fence = !fence;
        if (fence) continue;
        std::string line;
        bool code = false;
        for (const char c : raw) {
            if (c == '`') code = !code;
            else if (!code) line += c;
        }
        for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
            const std::size_t end = line.find_first_of(") ", at + 2);
            links.push_back({number, line.substr(at + 2, end == std::string::npos ? end : end - at - 2)});
        }
    }
    return links;
}

std::vector<fs::path> documents() {
    std::vector<fs::path> files = {kSource / "README.md"};
    for (const auto& entry : fs::directory_iterator(kSource / "docs"))
        if (entry.path().extension() == ".md") files.push_back(entry.path());
    return files;
}

TEST(DocLinks, EveryRelativeLinkAndAnchorResolves) {
    std::size_t checked = 0;
    for (const fs::path& document : documents()) {
        const std::string name = fs::relative(document, kSource).string();
        for (const Link& link : linksOf(document)) {
            const std::string& target = link.target;
            if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target.rfind("mailto:", 0) == 0)
                continue;
            ++checked;
            const std::size_t hash = target.find('#');
            const std::string file = target.substr(0, hash);
            const fs::path resolved = file.empty() ? document : document.parent_path() / file;
            const std::string where = name + ":" + std::to_string(link.line) + ": " + target;
            if (!fs::exists(resolved)) {
                ADD_FAILURE() << where << ": no such file";
                continue;
            }
            if (hash == std::string::npos) continue;
            if (resolved.extension() != ".md") {
                ADD_FAILURE() << where << ": an anchor into a file that is not Markdown";
                continue;
            }
            const std::string anchor = target.substr(hash + 1);
            if (!anchorsOf(resolved).contains(anchor))
                ADD_FAILURE() << where << ": no heading in " << fs::relative(resolved, kSource).string()
                              << " has the anchor #" << anchor;
        }
    }
    EXPECT_GT(checked, 50u) << "the link parser found almost no links";
}

TEST(DocLinks, TheReadmeTestCommandIsTheOneCiRuns) {
    // The second ```sh block of the README, and the last command of .ci/run.
    std::vector<std::string> blocks;
    bool inside = false;
    for (const std::string& line : readLines(kSource / "README.md")) {
        if (isFence(line)) {
            inside = !inside;
            if (inside) blocks.emplace_back();
        } else if (inside) {
            blocks.back() += line;
        }
    }
    ASSERT_GE(blocks.size(), 2u);
    std::string last;
    for (const std::string& line : readLines(kSource / ".ci" / "run"))
        if (!line.empty()) last = line;
    EXPECT_EQ(blocks[1], last);
}

}  // namespace
