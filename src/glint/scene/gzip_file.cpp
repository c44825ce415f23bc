// Whole-file reads with transparent gunzip (zlib's inflate, streamed in 64 KiB blocks), the
// size limit checked on every block so that neither a large file nor a gzip bomb fills memory.
#include "glint/scene/gzip_file.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "glint/scene/read_sandbox.h"

namespace glint {

namespace {

constexpr std::size_t kBlock = std::size_t(1) << 16;

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

class Reader {
public:
    Reader(const std::filesystem::path& file, std::uint64_t max_bytes)
        : name_(file.string()), max_bytes_(max_bytes) {}

    SceneError fail(const std::string& why) const {
        return SceneError({name_, 0, 0}, "cannot read scene file: " + why);
    }
    SceneError too_large(const char* what) const {
        return SceneError(
            {name_, 0, 0},
            std::string("scene file ") + what + " the limit of " + describe_file_limit(max_bytes_),
            {kRaiseFileLimitNote});
    }

    // Appends n bytes to text unless that passes the limit.
    void append(std::string& text, const void* data, std::size_t n, const char* what) const {
        if (n > max_bytes_ - std::min<std::uint64_t>(max_bytes_, text.size())) {
            throw too_large(what);
        }
        text.append(static_cast<const char*>(data), n);
    }

    const std::string& name() const { return name_; }

private:
    std::string name_;
    std::uint64_t max_bytes_;
};

struct InflateEnd {
    void operator()(z_stream* s) const { inflateEnd(s); }
};

// Inflates the gzip members from `f`, whose first `n` bytes are already in `in`.
std::string gunzip(const Reader& reader, std::FILE* f, std::vector<unsigned char>& in,
                   std::size_t n, std::uint64_t size_hint) {
    z_stream stream{};
    if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) throw reader.fail("zlib failed to start");
    const std::unique_ptr<z_stream, InflateEnd> end(&stream);
    std::string text;
    text.reserve(size_hint);
    std::vector<unsigned char> out(kBlock);
    stream.next_in = in.data();
    stream.avail_in = unsigned(n);
    bool member_ended = false;
    for (;;) {
        if (stream.avail_in == 0) {
            const std::size_t got = std::fread(in.data(), 1, in.size(), f);
            if (got == 0) {
                if (std::ferror(f)) throw reader.fail(std::strerror(errno));
                break;
            }
            stream.next_in = in.data();
            stream.avail_in = unsigned(got);
        }
        if (member_ended) {
            // gzip files may hold several members, to be joined. Anything else after the first
            // fails inflate's header check below.
            inflateReset(&stream);
            member_ended = false;
        }
        stream.next_out = out.data();
        stream.avail_out = unsigned(out.size());
        const int status = inflate(&stream, Z_NO_FLUSH);
        reader.append(text, out.data(), out.size() - stream.avail_out, "decompresses to more than");
        if (status == Z_STREAM_END) {
            member_ended = true;
        } else if (status == Z_BUF_ERROR && stream.avail_in == 0) {
            // Needs more input: read on, or find that the file ends here.
        } else if (status != Z_OK) {
            if (status == Z_MEM_ERROR) throw std::bad_alloc();
            throw reader.fail(
                std::string("corrupt gzip data (") +
                (stream.msg ? stream.msg : "inflate error " + std::to_string(status)) + ")");
        }
    }
    if (!member_ended) throw reader.fail("the gzip data is truncated");
    return text;
}

std::uint64_t little_endian32(const unsigned char* b) {
    return b[0] | (std::uint64_t(b[1]) << 8) | (std::uint64_t(b[2]) << 16) |
           (std::uint64_t(b[3]) << 24);
}

// The uncompressed size a gzip file's last member claims (ISIZE, RFC 1952), for reserving
// memory; 0 when it cannot be read. Only a hint: it is one member's size modulo 2^32, and a
// hostile file may claim anything (the limit applies regardless).
std::uint64_t claimed_size(const Reader& reader, std::FILE* f, long resume_at) {
    unsigned char isize[4];
    std::uint64_t size = 0;
    if (std::fseek(f, -4, SEEK_END) == 0 && std::fread(isize, 1, 4, f) == 4) {
        size = little_endian32(isize);
    }
    if (std::fseek(f, resume_at, SEEK_SET) != 0) throw reader.fail(std::strerror(errno));
    return size;
}

}  // namespace

std::string read_maybe_gzipped(const std::filesystem::path& file, std::uint64_t max_bytes) {
    const Reader reader(file, max_bytes);
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (ec) throw reader.fail(ec.message());
    if (std::filesystem::is_directory(status)) throw reader.fail("it is a directory");
    std::uint64_t file_size = 0;
    const bool regular = std::filesystem::is_regular_file(status);
    if (regular) {
        file_size = std::filesystem::file_size(file, ec);
        if (ec) throw reader.fail(ec.message());
    }

    const std::unique_ptr<std::FILE, FileCloser> f(std::fopen(reader.name().c_str(), "rb"));
    if (!f) throw reader.fail(std::strerror(errno));
    std::vector<unsigned char> in(kBlock);
    const std::size_t n = std::fread(in.data(), 1, in.size(), f.get());
    if (n == 0 && std::ferror(f.get())) throw reader.fail(std::strerror(errno));

    if (n >= 2 && in[0] == 0x1f && in[1] == 0x8b) {
        std::uint64_t hint = 0;
        if (n < in.size()) {
            if (n >= 4) hint = little_endian32(&in[n - 4]);  // the whole file is in `in`
        } else if (regular) {
            hint = claimed_size(reader, f.get(), long(n));
        }
        // Deflate expands at most 1032:1, so a small file that claims more is lying.
        const std::uint64_t most = std::max<std::uint64_t>(file_size, n) * 1032;
        return gunzip(reader, f.get(), in, n, std::min({hint, most, max_bytes}));
    }
    if (file.extension() == ".gz") throw reader.fail("it is named .gz but is not gzip-compressed");

    // A regular file is measured first; pipes and devices are caught by the bounded reads.
    if (regular && file_size > max_bytes) throw reader.too_large("is larger than");
    std::string text;
    if (regular) text.reserve(std::size_t(file_size));
    reader.append(text, in.data(), n, "is larger than");
    while (const std::size_t got = std::fread(in.data(), 1, in.size(), f.get())) {
        reader.append(text, in.data(), got, "is larger than");
    }
    if (std::ferror(f.get())) throw reader.fail(std::strerror(errno));
    return text;
}

}  // namespace glint
