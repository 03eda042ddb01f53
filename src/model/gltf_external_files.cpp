// The files a glTF document names (external buffers and images). tinygltf finds each through our
// file-system callbacks, so every read is decided here: a URI is a relative path that must lead,
// after "..", percent-decoding (tinygltf's) and symbolic links, to a regular file inside the asset
// root; anything else is refused, and the refusal names the URI, not what lies outside.
#include <cctype>
#include <fstream>
#include <system_error>

#include "model/gltf_internal.h"
#include "model/gltf_loader.h"

namespace model::gltf {
namespace {

// tinygltf joins its search directory and the decoded URI this way (JoinPath in tiny_gltf.h).
std::string joined(const std::string& directory) {
    if (directory.empty() || directory.back() == '/') return directory;
    return directory + "/";
}

// "file:", "http:", "C:" ...: RFC 3986's scheme. A glTF file's own files are relative references.
bool hasScheme(const std::string& uri) {
    const std::size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (std::size_t i = 1; i < colon; ++i) {
        const char c = uri[i];
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return true;
}

bool hasControlCharacter(const std::string& uri) {
    for (const char c : uri)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) return true;
    return false;
}

// Whether `path` is `root` or below it, both canonical.
bool within(const std::filesystem::path& path, const std::filesystem::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p)
        if (p == path.end() || *p != *r) return false;
    return true;
}

bool fileExists(const std::string& path, void* user) {
    return static_cast<ExternalFiles*>(user)->resolve(path).has_value();
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    return static_cast<ExternalFiles*>(user)->read(path, *out, err);
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

}  // namespace

ExternalFiles::ExternalFiles(const std::filesystem::path& baseDir, const std::filesystem::path& assetRoot)
    : prefix_(baseDir.empty() ? std::string() : joined(baseDir.string())),
      baseDir_(baseDir),
      rootIsModelFolder_(assetRoot.empty()) {
    if (baseDir.empty()) return;
    const std::filesystem::path root = assetRoot.empty() ? baseDir : assetRoot;
    std::error_code error;
    root_ = std::filesystem::canonical(root, error);
    if (error || !std::filesystem::is_directory(root_, error))
        fail("the asset root " + root.string() + " is not a folder");
}

tinygltf::FsCallbacks ExternalFiles::callbacks() {
    return {&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, this};
}

std::optional<std::filesystem::path> ExternalFiles::resolve(const std::string& path) {
    // Nothing for a document from memory. tinygltf looks in the document's folder, then in the working
    // directory: only the first counts.
    if (prefix_.empty() || path.compare(0, prefix_.size(), prefix_) != 0) return std::nullopt;
    const std::string uri = path.substr(prefix_.size());
    const auto refuse = [&](const std::string& why) -> std::optional<std::filesystem::path> {
        if (refusal_.empty()) refusal_ = "URI '" + uri + "' " + why;
        return std::nullopt;
    };
    if (uri.empty()) return refuse("is empty");
    if (hasControlCharacter(uri)) return refuse("has control characters");
    if (hasScheme(uri)) return refuse("is not a relative path (file: and other schemes are not read)");
    if (uri.front() == '/') return refuse("is an absolute path (only paths relative to the model are read)");
    std::error_code error;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(baseDir_ / uri, error);
    if (error) return std::nullopt;  // tinygltf: "File not found"
    if (!within(resolved, root_))
        return refuse(rootIsModelFolder_ ? "leads outside the model's folder (a wider asset root, the assetRoot argument, allows it)"
                                         : "leads outside the asset root");
    // Regular files only: a FIFO or a device named by a URI would block or never end.
    if (!std::filesystem::is_regular_file(resolved, error)) return std::nullopt;
    return resolved;
}

bool ExternalFiles::read(const std::string& path, std::vector<unsigned char>& out, std::string* err) {
    const std::optional<std::filesystem::path> file = resolve(path);
    if (!file) {
        if (err) *err += "not a readable file";
        return false;
    }
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(*file, error);
    // A thousand buffers may name one big file: the budget is for all of them together.
    if (error || size > kMaxGltfFileBytes - bytesRead_) {
        if (err) *err += "external files larger than 1 GiB in all";
        return false;
    }
    bytesRead_ += size;
    std::ifstream stream(*file, std::ios::binary);
    out.resize(static_cast<std::size_t>(size));
    if (!stream || !stream.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size))) {
        if (err) *err += "cannot read it";
        return false;
    }
    return true;
}

}  // namespace model::gltf
