// Broadcast: a flag (1: files follow), the scene's path, the folders it may read, then each file
// as its path and bytes, every length first and bytes in pieces of at most 256 MiB.
#include "scene_broadcast.h"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/image/file_io.h"
#include "glint/scene/read_sandbox.h"

namespace glint::cli {

namespace {

constexpr std::uint64_t kPiece = std::uint64_t(1) << 28;

void broadcast_bytes(char* data, std::uint64_t size) {
    for (std::uint64_t at = 0; at < size; at += kPiece)
        MPI_Bcast(data + at, int(std::min(kPiece, size - at)), MPI_BYTE, 0, MPI_COMM_WORLD);
}

void send_u64(std::uint64_t v) { MPI_Bcast(&v, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD); }
std::uint64_t receive_u64() {
    std::uint64_t v = 0;
    MPI_Bcast(&v, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    return v;
}

void send_text(std::string text) {
    send_u64(text.size());
    broadcast_bytes(text.data(), text.size());
}
std::string receive_text() {
    std::string text(receive_u64(), '\0');
    broadcast_bytes(text.data(), text.size());
    return text;
}

// Where a file of rank 0 goes under `folder`: its absolute path below it.
std::filesystem::path under(const std::filesystem::path& folder, const std::string& path) {
    return folder / std::filesystem::path(path).relative_path();
}

}  // namespace

std::uint64_t share_scene(const std::filesystem::path& scene_file, const Scene& scene,
                          const LoadOptions& options) {
    std::uint64_t sent = 0;
    send_u64(1);
    const std::string own = resolve_path(scene_file).value_or(scene_file).string();
    send_text(own);
    send_u64(options.allow_read.size());
    for (const std::filesystem::path& folder : options.allow_read)
        send_text(resolve_path(folder).value_or(folder).string());
    std::vector<std::string> files = {own};
    for (const std::filesystem::path& file : scene.sources.files_read)
        files.push_back(file.string());
    send_u64(files.size());
    for (const std::string& file : files) {
        send_text(file);
        const std::vector<unsigned char> bytes = read_whole_file(file);
        send_u64(bytes.size());
        broadcast_bytes(reinterpret_cast<char*>(const_cast<unsigned char*>(bytes.data())),
                        bytes.size());
        sent += bytes.size();
    }
    return sent;
}

void share_failure() { send_u64(0); }

// 0 says there is none; kWholeFrames (-1) and the frames' numbers follow.
void share_frame(int frame) { send_u64(std::uint64_t(frame + 2)); }
void share_end_of_frames() { send_u64(0); }

std::optional<int> receive_frame() {
    const std::uint64_t v = receive_u64();
    if (v == 0) return std::nullopt;
    return int(v) - 2;
}

std::optional<Scene> receive_scene(const std::filesystem::path& folder, LoadOptions options) {
    if (receive_u64() == 0) return std::nullopt;
    const std::string scene_file = receive_text();
    // The folders it may read, under `folder`, and as they are on this host: a scene that names
    // a file by its absolute path reads it from this host's disk (checked below).
    options.allow_read.clear();
    std::vector<std::filesystem::path> own_disk;
    for (std::uint64_t n = receive_u64(); n > 0; --n) {
        const std::string allowed = receive_text();
        options.allow_read.push_back(under(folder, allowed));
        if (std::filesystem::is_directory(allowed)) own_disk.push_back(allowed);
    }
    for (std::uint64_t n = receive_u64(); n > 0; --n) {
        const std::filesystem::path path = under(folder, receive_text());
        std::string bytes(receive_u64(), '\0');
        broadcast_bytes(bytes.data(), bytes.size());
        std::filesystem::create_directories(path.parent_path());
        UniqueFile out = open_file(path, "wb");
        write_bytes(out.get(), bytes.data(), bytes.size(), path);
        close_written_file(std::move(out), path);
    }
    for (const std::filesystem::path& allowed : options.allow_read)
        std::filesystem::create_directories(allowed);
    options.allow_read.insert(options.allow_read.end(), own_disk.begin(), own_disk.end());
    Scene scene = load_scene(under(folder, scene_file), options);
    // A file read from this host's disk must be the one rank 0 read.
    for (const std::filesystem::path& read : scene.sources.files_read) {
        if (is_inside(read, folder)) continue;
        const std::filesystem::path sent = under(folder, read.string());
        std::error_code error;
        if (!std::filesystem::exists(sent, error) || read_whole_file(read) != read_whole_file(sent))
            throw std::runtime_error("the scene reads " + read.string() +
                                     " on this host, and it is not the file rank 0 read: give "
                                     "every host the same file, or a path relative to the scene");
    }
    return scene;
}

}  // namespace glint::cli
