// A file of ClosingIOSystem: Assimp's stream inside, and a word to the system when it goes.
#include "glint/scene/mesh/closing_io_system.h"

#include <assimp/IOStream.hpp>
#include <memory>
#include <utility>
#include <vector>

namespace glint {

namespace {

class TrackedStream : public Assimp::IOStream {
public:
    TrackedStream(std::unique_ptr<Assimp::IOStream> inner, ClosingIOSystem& system)
        : inner_(std::move(inner)), system_(system) {}
    ~TrackedStream() override { system_.forget(this); }

    size_t Read(void* buffer, size_t size, size_t count) override {
        return inner_->Read(buffer, size, count);
    }
    size_t Write(const void* buffer, size_t size, size_t count) override {
        return inner_->Write(buffer, size, count);
    }
    aiReturn Seek(size_t offset, aiOrigin origin) override { return inner_->Seek(offset, origin); }
    size_t Tell() const override { return inner_->Tell(); }
    size_t FileSize() const override { return inner_->FileSize(); }
    void Flush() override { inner_->Flush(); }

private:
    std::unique_ptr<Assimp::IOStream> inner_;
    ClosingIOSystem& system_;
};

}  // namespace

ClosingIOSystem::~ClosingIOSystem() {
    // Deleting a file erases it from open_: walk a copy.
    const std::vector<Assimp::IOStream*> left(open_.begin(), open_.end());
    for (Assimp::IOStream* stream : left) delete stream;
}

Assimp::IOStream* ClosingIOSystem::Open(const char* file, const char* mode) {
    std::unique_ptr<Assimp::IOStream> inner(DefaultIOSystem::Open(file, mode));
    if (!inner) return nullptr;
    auto* stream = new TrackedStream(std::move(inner), *this);
    open_.insert(stream);
    return stream;
}

}  // namespace glint
