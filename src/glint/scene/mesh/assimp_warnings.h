// The warnings Assimp logs during one import, captured so that the importer can report what
// Assimp only logs (glTF faces it drops for out-of-range indices). Internal to the mesh importer.
#pragma once

#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// Installs a logger for the object's lifetime and removes it after. Assimp's logger is one for
// the process, so captures (and the imports inside them) are serialised by a lock. At most
// kMaxMessages messages are kept, each cut to kMaxLength characters: a hostile file cannot grow
// them without bound.
class AssimpWarnings {
public:
    static constexpr std::size_t kMaxMessages = 64;
    static constexpr std::size_t kMaxLength = 400;

    AssimpWarnings();
    ~AssimpWarnings();
    AssimpWarnings(const AssimpWarnings&) = delete;
    AssimpWarnings& operator=(const AssimpWarnings&) = delete;

    // Warnings and errors, in the order Assimp logged them.
    const std::vector<std::string>& messages() const { return messages_; }
    bool any_contains(std::string_view text) const;

private:
    std::unique_lock<std::mutex> lock_;
    std::vector<std::string> messages_;  // the logger appends to it
};

}  // namespace glint
