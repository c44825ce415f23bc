// Assimp's file access with every file that an import leaves open closed when the importer
// goes: Assimp 5.2's glTF reader leaks the stream of a buffer file shorter than its byteLength.
// Internal to the mesh importer.
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <set>

namespace glint {

// Hands out its files wrapped, so that it knows which ones are still open however Assimp ends
// them (Close() or a plain delete); the Importer owns it and deletes it last.
class ClosingIOSystem : public Assimp::DefaultIOSystem {
public:
    ClosingIOSystem() = default;
    ClosingIOSystem(const ClosingIOSystem&) = delete;
    ClosingIOSystem& operator=(const ClosingIOSystem&) = delete;
    ~ClosingIOSystem() override;

    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    // Called by a file when it is deleted.
    void forget(Assimp::IOStream* stream) { open_.erase(stream); }

private:
    std::set<Assimp::IOStream*> open_;
};

}  // namespace glint
