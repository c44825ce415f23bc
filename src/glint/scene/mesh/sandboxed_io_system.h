// Assimp's file access for one import, kept inside the sandbox: Assimp opens the model file and
// the files it names (glTF buffers, OBJ material libraries) itself, and its default IOSystem
// would open any of them. Internal to glint_scene: Assimp stays private.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "glint/scene/mesh/closing_io_system.h"
#include "glint/scene/read_sandbox.h"

namespace glint {

class SandboxedIOSystem : public ClosingIOSystem {
public:
    // The model file itself may be read wherever it is: the scene or the user named it.
    SandboxedIOSystem(ReadSandbox sandbox, const std::filesystem::path& model_file);

    bool Exists(const char* file) const override;
    // Opens for reading only; a refused file gives nullptr, as a missing one does.
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

    // The first path refused, as Assimp asked for it: Assimp reports the failure as a file it
    // could not open, and the loader says why instead.
    const std::optional<std::string>& refused() const { return refused_; }

private:
    bool allowed(const char* file) const;

    ReadSandbox sandbox_;
    std::optional<std::filesystem::path> model_file_;  // resolved
    mutable std::optional<std::string> refused_;
};

}  // namespace glint
