// Bytes written and read as little-endian numbers, floats as their bits, so that values come
// back exactly: a resume file's state, and the messages between the ranks of a cluster.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "glint/render/film/film.h"

namespace glint {

class ByteWriter {
public:
    ByteWriter() = default;
    // Hands the bytes to `sink` in pieces of about a mebibyte as they come, instead of keeping
    // them all: a render's state is as large as its film.
    explicit ByteWriter(std::function<void(const std::string&)> sink) : sink_(std::move(sink)) {}

    void u8(std::uint8_t v) {
        bytes_.push_back(char(v));
        if (sink_ && bytes_.size() >= kPiece) flush();
    }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) u8(std::uint8_t(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) u8(std::uint8_t(v >> (8 * i)));
    }
    void i32(int v) { u32(std::uint32_t(v)); }
    void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
    void i128(FixedSum v) {
        u64(std::uint64_t(v));  // the low bits, then the high: two's complement
        u64(std::uint64_t(v >> 64));
    }
    void text(std::string_view s) {
        u32(std::uint32_t(s.size()));
        raw(s.data(), s.size());
    }
    void raw(const void* data, std::size_t n) {
        bytes_.append(static_cast<const char*>(data), n);
        if (sink_ && bytes_.size() >= kPiece) flush();
    }
    // Hands what is left to the sink.
    void flush() {
        if (!bytes_.empty()) sink_(bytes_);
        bytes_.clear();
    }
    std::string& bytes() { return bytes_; }

private:
    static constexpr std::size_t kPiece = std::size_t(1) << 20;
    std::function<void(const std::string&)> sink_;
    std::string bytes_;
};

// Reads what ByteWriter wrote; running past the end throws Error(truncated).
template <class Error = std::runtime_error>
class ByteReader {
public:
    ByteReader(const unsigned char* data, std::size_t size, std::string truncated)
        : data_(data), size_(size), truncated_(std::move(truncated)) {}

    const unsigned char* take(std::size_t n) {
        if (n > size_ - at_) throw Error(truncated_);
        const unsigned char* p = data_ + at_;
        at_ += n;
        return p;
    }
    std::uint8_t u8() { return *take(1); }
    std::uint32_t u32() {
        const unsigned char* p = take(4);
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(p[i]) << (8 * i);
        return v;
    }
    std::uint64_t u64() {
        const unsigned char* p = take(8);
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= std::uint64_t(p[i]) << (8 * i);
        return v;
    }
    int i32() { return int(u32()); }
    float f32() { return std::bit_cast<float>(u32()); }
    double f64() { return std::bit_cast<double>(u64()); }
    FixedSum i128() {
        const std::uint64_t low = u64(), high = u64();
        return FixedSum(std::int64_t(high)) * (FixedSum(1) << 64) + FixedSum(low);
    }
    std::string text() {
        const std::uint32_t n = u32();
        const unsigned char* p = take(n);
        return {reinterpret_cast<const char*>(p), n};
    }
    std::size_t left() const { return size_ - at_; }

private:
    const unsigned char* data_;
    std::size_t size_, at_ = 0;
    std::string truncated_;
};

}  // namespace glint
