// Temporary-then-rename file writing; rename(2) within one directory is atomic on POSIX.
#include "glint/image/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "glint/image/image_error.h"

namespace glint {
namespace {

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    // pid separates processes, the counter separates threads and calls of one process.
    static std::atomic<unsigned> counter{0};
    // Built by appending: GCC 12's -Wrestrict misfires on `"." + std::string` (PR 105329).
    std::string name = ".";
    name += target.stem().string();
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    name += target.extension().string();
    return target.parent_path() / name;
}

// The writer's message with every mention of the temporary (libraries such as OpenEXR quote the
// file they opened) replaced by the target.
std::string mention_target(std::string message, const std::filesystem::path& temporary,
                           const std::filesystem::path& target) {
    const std::string from = temporary.string(), to = target.string();
    for (auto at = message.find(from); at != std::string::npos; at = message.find(from, at)) {
        message.replace(at, from.size(), to);
        at += to.size();
    }
    return message;
}

void remove_quietly(const std::filesystem::path& path) {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}

// Flushes the new contents to disk before the rename publishes them; otherwise a power cut soon
// after can leave an empty file where a good image used to be. A disk that fills up only now
// (delayed allocation, network file systems) says so here: the new file is then not whole.
void sync_file(const std::filesystem::path& path, const std::filesystem::path& target) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw ImageError(
            target, std::string("cannot open the written file again: ") + std::strerror(errno));
    if (::fsync(fd) != 0) {
        const std::string reason = std::strerror(errno);
        ::close(fd);
        throw ImageError(target, "cannot flush the written file to disk: " + reason);
    }
    ::close(fd);
}

}  // namespace

void write_file_atomically(
    const std::filesystem::path& target,
    const std::function<void(const std::filesystem::path& temporary)>& write) {
    const std::filesystem::path temporary = temporary_path_for(target);
    try {
        write(temporary);
    } catch (const ImageError& e) {
        remove_quietly(temporary);
        if (e.file == temporary) {
            throw ImageError(target, mention_target(e.detail, temporary, target));
        }
        throw;
    } catch (...) {
        remove_quietly(temporary);
        throw;
    }
    try {
        sync_file(temporary, target);
    } catch (...) {
        remove_quietly(temporary);
        throw;
    }
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) {
        remove_quietly(temporary);
        throw ImageError(target, "cannot move the finished file into place: " + error.message());
    }
}

}  // namespace glint
