// The sandbox check: a path is resolved (so that "..", absolute paths and symbolic links all
// count for where they lead) and must lie inside one of the allowed folders.
#include "glint/scene/read_sandbox.h"

#include <algorithm>
#include <system_error>

#include "glint/scene/quote.h"
#include "glint/scene/scene_error.h"

namespace glint {

std::optional<std::filesystem::path> resolve_path(const std::filesystem::path& path) {
    std::error_code ec;
    // weakly_canonical leaves a relative path relative when none of it exists; absolute() first
    // makes every result comparable with the folders.
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    if (ec) return std::nullopt;
    std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, ec);
    if (ec) return std::nullopt;
    return resolved;
}

bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    auto part = path.begin();
    for (const std::filesystem::path& component : folder) {
        if (component.empty()) continue;  // the empty last component of a trailing separator
        if (part == path.end() || *part != component) return false;
        ++part;
    }
    return true;
}

std::string describe_file_limit(std::uintmax_t bytes) {
    constexpr std::uintmax_t kMiB = std::uintmax_t(1) << 20;
    if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
    return std::to_string(bytes) + " bytes";
}

ReadSandbox make_read_sandbox(const std::filesystem::path& scene_file,
                              std::span<const std::filesystem::path> allowed,
                              std::optional<std::uintmax_t> max_file_bytes) {
    ReadSandbox sandbox;
    sandbox.max_file_bytes = max_file_bytes;
    const std::filesystem::path own = scene_file.parent_path();
    // A scene's folder that cannot be resolved allows nothing: every read is refused.
    if (const auto folder = resolve_path(own.empty() ? "." : own))
        sandbox.folders.push_back(*folder);
    for (const std::filesystem::path& folder : allowed) {
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec)) {
            throw SceneError({folder.string(), 0, 0},
                             std::filesystem::exists(folder, ec)
                                 ? "the folder allowed to be read is not a folder"
                                 : "the folder allowed to be read does not exist");
        }
        if (const auto resolved = resolve_path(folder)) sandbox.folders.push_back(*resolved);
    }
    return sandbox;
}

namespace {

bool inside_a_folder(const ReadSandbox& sandbox, const std::filesystem::path& resolved) {
    for (const std::filesystem::path& folder : sandbox.folders) {
        if (is_inside(resolved, folder)) return true;
    }
    return false;
}

// Whether `resolved` names something other than a regular file: a folder, a pipe, a device.
bool is_special(const std::filesystem::path& resolved) {
    std::error_code ec;
    const auto status = std::filesystem::status(resolved, ec);
    return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

}  // namespace

bool may_read(const ReadSandbox& sandbox, const std::filesystem::path& path) {
    const auto resolved = resolve_path(path);
    return resolved && inside_a_folder(sandbox, *resolved) && !is_special(*resolved);
}

void record_read(const ReadSandbox& sandbox, const std::filesystem::path& path) {
    const auto resolved = resolve_path(path);
    if (!resolved) return;
    std::vector<std::filesystem::path>& files = *sandbox.files_read;
    if (std::find(files.begin(), files.end(), *resolved) == files.end()) files.push_back(*resolved);
}

std::optional<ReadRefusal> check_read(const ReadSandbox& sandbox, const std::filesystem::path& path,
                                      std::string_view what, std::string_view written) {
    const auto resolved = resolve_path(path);
    if (resolved && inside_a_folder(sandbox, *resolved)) {
        if (!is_special(*resolved)) return std::nullopt;
        return ReadRefusal{
            std::string(what) + " " + quote(written, written.size()) + " is not a regular file",
            {"it resolves to " + resolved->string()}};
    }
    ReadRefusal refusal;
    // A path is quoted whole, however long: the user must see which file it is.
    refusal.message = std::string(what) + " " + quote(written, written.size()) +
                      " is outside the folders the scene may read";
    refusal.notes.push_back(resolved ? "it resolves to " + resolved->string()
                                     : "where it leads cannot be worked out");
    std::string folders;
    for (const std::filesystem::path& folder : sandbox.folders) {
        folders += (folders.empty() ? "" : ", ") + folder.string();
    }
    refusal.notes.push_back("the scene may read files under " +
                            (folders.empty() ? std::string("no folder") : folders));
    refusal.notes.push_back("allow the folder with --allow-read DIR");
    return refusal;
}

}  // namespace glint
