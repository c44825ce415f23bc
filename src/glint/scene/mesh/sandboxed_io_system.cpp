// The sandboxed IOSystem: Assimp's file access (closing what an import leaves open) behind the
// sandbox check.
#include "glint/scene/mesh/sandboxed_io_system.h"

#include <utility>

namespace glint {

SandboxedIOSystem::SandboxedIOSystem(ReadSandbox sandbox, const std::filesystem::path& model_file)
    : sandbox_(std::move(sandbox)), model_file_(resolve_path(model_file)) {}

bool SandboxedIOSystem::allowed(const char* file) const {
    if (model_file_ && resolve_path(file) == model_file_) return true;
    if (may_read(sandbox_, file)) return true;
    if (!refused_) refused_ = file;
    return false;
}

bool SandboxedIOSystem::Exists(const char* file) const {
    return allowed(file) && DefaultIOSystem::Exists(file);
}

Assimp::IOStream* SandboxedIOSystem::Open(const char* file, const char* mode) {
    // Importers only read; glint never lets one write.
    if (mode == nullptr || mode[0] != 'r' || std::string(mode).find('+') != std::string::npos) {
        return nullptr;
    }
    if (!allowed(file)) return nullptr;
    Assimp::IOStream* stream = ClosingIOSystem::Open(file, mode);
    if (stream != nullptr) record_read(sandbox_, file);
    return stream;
}

}  // namespace glint
