// A logger for Assimp that keeps its warnings and errors; see assimp_warnings.h.
#include "glint/scene/mesh/assimp_warnings.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Logger.hpp>

namespace glint {

namespace {

std::mutex capture_mutex;

class CollectingLogger : public Assimp::Logger {
public:
    explicit CollectingLogger(std::vector<std::string>& messages) : messages_(messages) {}

    void OnDebug(const char*) override {}
    void OnVerboseDebug(const char*) override {}
    void OnInfo(const char*) override {}
    void OnWarn(const char* message) override { keep(message); }
    void OnError(const char* message) override { keep(message); }
    bool attachStream(Assimp::LogStream*, unsigned int) override { return false; }
    bool detachStream(Assimp::LogStream*, unsigned int) override { return false; }

private:
    void keep(const char* message) {
        if (messages_.size() >= AssimpWarnings::kMaxMessages) return;
        std::string text(message);
        if (text.size() > AssimpWarnings::kMaxLength) text.resize(AssimpWarnings::kMaxLength);
        messages_.push_back(std::move(text));
    }

    std::vector<std::string>& messages_;
};

}  // namespace

AssimpWarnings::AssimpWarnings() : lock_(capture_mutex) {
    // Assimp owns the logger from here on, and deletes it in kill().
    Assimp::DefaultLogger::set(new CollectingLogger(messages_));
}

AssimpWarnings::~AssimpWarnings() { Assimp::DefaultLogger::kill(); }

bool AssimpWarnings::any_contains(std::string_view text) const {
    for (const std::string& m : messages_) {
        if (m.find(text) != std::string::npos) return true;
    }
    return false;
}

}  // namespace glint
