// Writing and reading resume files: a plain header of the render's identity, checked field by
// field so that a refusal names what differs, then the state, zlib-compressed with a CRC-32.
// Numbers are little-endian; floats are stored as their bits, so the state comes back exactly.
#include "glint/render/resume_file.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>
#include <functional>
#include <sstream>
#include <vector>

#include "glint/image/atomic_file.h"
#include "glint/image/file_io.h"
#include "glint/image/image_error.h"
#include "glint/render/byte_stream.h"
#include "glint/render/counts_codec.h"
#include "glint/scene/scene_limits.h"

namespace glint {

namespace {

constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'R', 'E', 'S'};
// 3: an adaptive render's film holds each pixel's own weighted samples (filter importance
// sampling); 4: rays of five kinds (diffuse); 5: of six (particles), the particles' counts, and
// the light integrator's film of particles; 6: the photons stored; 8: the working space and the
// part of the render.
constexpr std::uint32_t kFormatVersion = 8;

// Deflates what it is given into a file as it comes, and sums the CRC-32 of what it was given.
class DeflateToFile {
public:
    DeflateToFile(std::FILE* file, const std::filesystem::path& path)
        : file_(file), path_(path), out_(std::size_t(1) << 16) {
        // The fastest level: the sums of a noisy image hardly compress further, and a
        // checkpoint should not stall the render.
        if (deflateInit(&stream_, Z_BEST_SPEED) != Z_OK) fail();
    }
    ~DeflateToFile() { deflateEnd(&stream_); }
    DeflateToFile(const DeflateToFile&) = delete;
    DeflateToFile& operator=(const DeflateToFile&) = delete;

    void add(const std::string& bytes) {
        crc_ = crc32(crc_, reinterpret_cast<const Bytef*>(bytes.data()), uInt(bytes.size()));
        run(bytes.data(), bytes.size(), Z_NO_FLUSH);
    }
    void finish() { run(nullptr, 0, Z_FINISH); }
    std::uint64_t given() const { return stream_.total_in; }
    std::uint64_t packed_size() const { return packed_; }
    std::uint32_t crc() const { return std::uint32_t(crc_); }

private:
    void run(const char* data, std::size_t size, int flush) {
        stream_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
        stream_.avail_in = uInt(size);
        do {  // until deflate leaves room in its output: then it has taken all the input
            stream_.next_out = out_.data();
            stream_.avail_out = uInt(out_.size());
            if (deflate(&stream_, flush) == Z_STREAM_ERROR) fail();
            const std::size_t made = out_.size() - stream_.avail_out;
            write_bytes(file_, out_.data(), made, path_);
            packed_ += made;
        } while (stream_.avail_out == 0);
    }
    [[noreturn]] void fail() const {
        throw ImageError(path_, "cannot compress the render's state");
    }

    std::FILE* file_;
    std::filesystem::path path_;
    z_stream stream_{};
    std::vector<Bytef> out_;
    uLong crc_ = crc32(0, nullptr, 0);
    std::uint64_t packed_ = 0;
};

// `path` as it is now. A pipe or a device is not read: its bytes could not be read again.
FileStamp stamp_file(const std::filesystem::path& path) {
    FileStamp stamp;
    stamp.path = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        stamp.readable = false;
        return stamp;
    }
    const UniqueFile file(std::fopen(stamp.path.c_str(), "rb"));
    if (!file) {
        stamp.readable = false;
        return stamp;
    }
    uLong crc = crc32(0, nullptr, 0);
    unsigned char buffer[1 << 16];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get())) {
        crc = crc32_z(crc, buffer, n);
        stamp.size += n;
    }
    stamp.readable = std::ferror(file.get()) == 0;
    stamp.crc = std::uint32_t(crc);
    return stamp;
}

template <class Kind>
std::string name_of(Kind kind, std::span<const std::string_view> names,
                    std::optional<Kind> (*from_name)(std::string_view)) {
    for (const std::string_view name : names)
        if (from_name(name) == kind) return std::string(name);
    return "?";
}

std::string describe(const FilterSpec& f) {
    std::ostringstream out;
    out << name_of(f.kind, filter_names(), filter_from_name) << " filter of radius " << f.radius;
    if (f.kind == FilterKind::gaussian) out << " and sigma " << f.sigma;
    if (f.kind == FilterKind::mitchell) out << ", B " << f.b << " and C " << f.c;
    return out.str();
}

std::string describe(const std::optional<AdaptiveSampling>& a) {
    if (!a) return "no adaptive sampling";
    std::ostringstream out;
    out << "adaptive sampling to " << a->threshold << " from " << a->min_samples << " samples";
    return out.str();
}

void write_identity(ByteWriter& out, const RenderIdentity& id) {
    out.raw(kMagic, sizeof kMagic);
    out.u32(kFormatVersion);
    out.text(id.glint_version);
    out.text(id.scene_path);
    out.u32(std::uint32_t(id.files.size()));
    for (const FileStamp& f : id.files) {
        out.text(f.path);
        out.u64(f.size);
        out.u32(f.crc);
        out.u8(f.readable ? 1 : 0);
    }
    out.i32(id.width);
    out.i32(id.height);
    out.i32(id.samples_per_pixel);
    out.u64(id.seed);
    out.u8(std::uint8_t(id.integrator));
    out.u8(std::uint8_t(id.sampler));
    out.u8(std::uint8_t(id.filter.kind));
    out.f32(id.filter.radius);
    out.f32(id.filter.sigma);
    out.f32(id.filter.b);
    out.f32(id.filter.c);
    out.i32(id.max_depth);
    out.u8(id.adaptive ? 1 : 0);
    out.f32(id.adaptive ? id.adaptive->threshold : 0);
    out.i32(id.adaptive ? id.adaptive->min_samples : 0);
    out.i32(id.tile_size);
    out.i32(id.pass_size);
    out.u8(std::uint8_t(id.working_space.transfer));
    out.f32(id.working_space.gamma);
    out.i32(id.part.index);
    out.i32(id.part.count);
    out.u8(std::uint8_t(id.part.split));
}

// The identity after the magic and format version, as written.
RenderIdentity read_identity(ByteReader<ResumeError>& in) {
    RenderIdentity id;
    id.glint_version = in.text();
    id.scene_path = in.text();
    const std::uint32_t files = in.u32();
    for (std::uint32_t i = 0; i < files; ++i) {
        FileStamp f;
        f.path = in.text();
        f.size = in.u64();
        f.crc = in.u32();
        f.readable = in.u8() != 0;
        id.files.push_back(std::move(f));
    }
    id.width = in.i32();
    id.height = in.i32();
    id.samples_per_pixel = in.i32();
    id.seed = in.u64();
    id.integrator = IntegratorKind(in.u8());
    id.sampler = SamplerKind(in.u8());
    id.filter.kind = FilterKind(in.u8());
    id.filter.radius = in.f32();
    id.filter.sigma = in.f32();
    id.filter.b = in.f32();
    id.filter.c = in.f32();
    id.max_depth = in.i32();
    const bool adaptive = in.u8() != 0;
    const float threshold = in.f32();
    const int min_samples = in.i32();
    if (adaptive) id.adaptive = AdaptiveSampling{threshold, min_samples};
    id.tile_size = in.i32();
    id.pass_size = in.i32();
    id.working_space.transfer = WorkingSpace::Transfer(in.u8());
    id.working_space.gamma = in.f32();
    id.part.index = in.i32();
    id.part.count = in.i32();
    id.part.split = PartSplit(in.u8());
    return id;
}

// What differs between the files two renders' scenes were made from, the scene file first:
// "written before /models/wood.png changed". Empty when they are the same.
std::string files_difference(const std::vector<FileStamp>& was, const std::vector<FileStamp>& now) {
    const auto named = [](const std::vector<FileStamp>& files, const std::string& path) {
        return std::find_if(files.begin(), files.end(),
                            [&](const FileStamp& f) { return f.path == path; });
    };
    for (std::size_t i = 0; i < now.size(); ++i) {
        const FileStamp& file = now[i];
        const auto before = named(was, file.path);
        if (before == was.end()) return "written for a scene that did not read " + file.path;
        if (!file.readable || !before->readable)
            return "written for a scene whose file " + file.path +
                   " cannot be checked for changes (it is not a regular file)";
        if (*before != file)
            return i == 0 ? "written for another scene (its file has changed since)"
                          : "written before " + file.path + " changed";
    }
    for (const FileStamp& file : was)
        if (named(now, file.path) == now.end())
            return "written for a scene that read " + file.path + ", which this one does not";
    return {};
}

}  // namespace

std::string identity_difference(const RenderIdentity& was, const RenderIdentity& now) {
    const auto num = [](auto v) { return std::to_string(v); };
    if (was.glint_version != now.glint_version)
        return "written by glint " + was.glint_version + ", this is glint " + now.glint_version;
    if (was.scene_path != now.scene_path)
        return "written for scene " + was.scene_path + ", not " + now.scene_path;
    if (const std::string why = files_difference(was.files, now.files); !why.empty()) return why;
    if (was.width != now.width || was.height != now.height)
        return "written for an image of " + num(was.width) + "x" + num(was.height) + ", not " +
               num(now.width) + "x" + num(now.height);
    if (was.samples_per_pixel != now.samples_per_pixel)
        return "written for " + num(was.samples_per_pixel) + " samples per pixel, not " +
               num(now.samples_per_pixel);
    if (was.seed != now.seed) return "written for seed " + num(was.seed) + ", not " + num(now.seed);
    if (was.integrator != now.integrator)
        return "written for the " +
               name_of(was.integrator, integrator_names(), integrator_from_name) +
               " integrator, not " +
               name_of(now.integrator, integrator_names(), integrator_from_name);
    if (was.sampler != now.sampler)
        return "written for the " + name_of(was.sampler, sampler_names(), sampler_from_name) +
               " sampler, not " + name_of(now.sampler, sampler_names(), sampler_from_name);
    if (!(was.filter == now.filter))
        return "written for a " + describe(was.filter) + ", not a " + describe(now.filter);
    if (was.max_depth != now.max_depth)
        return "written for max depth " + num(was.max_depth) + ", not " + num(now.max_depth);
    const bool same_adaptive =
        was.adaptive.has_value() == now.adaptive.has_value() &&
        (!was.adaptive || (was.adaptive->threshold == now.adaptive->threshold &&
                           was.adaptive->min_samples == now.adaptive->min_samples));
    if (!same_adaptive)
        return "written for " + describe(was.adaptive) + ", not " + describe(now.adaptive);
    if (was.tile_size != now.tile_size)
        return "written for tiles of " + num(was.tile_size) + " pixels, not " + num(now.tile_size);
    if (was.pass_size != now.pass_size)
        return "written for passes of " + num(was.pass_size) + " samples, not " +
               num(now.pass_size);
    if (was.working_space.transfer != now.working_space.transfer ||
        was.working_space.gamma != now.working_space.gamma)
        return std::string("written for another working space (assumed_gamma)");
    if (was.part != now.part)
        return "written for " + (was.part.whole() ? "the whole render" : describe(was.part)) +
               ", not " + (now.part.whole() ? "the whole render" : describe(now.part));
    return {};
}

namespace {

void encode_state(const RenderState& s, ByteWriter& out) {
    out.u32(std::uint32_t(s.tile_passes.size()));
    for (const int passes : s.tile_passes) out.i32(passes);
    write_counts(out, s.rays, s.bad_samples);
    out.f64(s.seconds);
    for (const std::uint32_t n : s.samples) out.u32(n);
    for (const PixelError& e : s.errors) {
        out.i32(e.n);
        out.f64(e.mean);
        out.f64(e.m2);
    }
    for (const BoxSum& b : s.film.box_sums()) {
        out.f32(b.sum.r);
        out.f32(b.sum.g);
        out.f32(b.sum.b);
        out.f32(b.weight);
    }
    for (const PixelSum& p : s.film.sums()) {
        out.i128(p.r);
        out.i128(p.g);
        out.i128(p.b);
        out.i128(p.weight);
    }
    if (s.splats)
        for (const std::int64_t v : s.splats->sums()) out.u64(std::uint64_t(v));
}

// The bytes encode_state writes for s, worked out without writing them.
std::uint64_t encoded_size(const RenderState& s) {
    return 4 + s.tile_passes.size() * 4 + kCountsSize + 8 + s.samples.size() * 4 +
           s.errors.size() * (4 + 8 + 8) + s.film.box_sums().size() * 4 * 4 +
           s.film.sums().size() * 4 * 16 + (s.splats ? s.splats->size() * 8 : 0);
}

// Decodes into `s`, a fresh state of the expected image, whose sizes the data must have.
void decode_state(ByteReader<ResumeError>& in, RenderState& s, const std::string& corrupt) {
    if (in.u32() != s.tile_passes.size()) throw ResumeError(corrupt);
    for (int& passes : s.tile_passes) passes = in.i32();
    read_counts(in, s.rays, s.bad_samples);
    s.seconds = in.f64();
    for (std::uint32_t& n : s.samples) n = in.u32();
    for (PixelError& e : s.errors) {
        e.n = in.i32();
        e.mean = in.f64();
        e.m2 = in.f64();
    }
    for (BoxSum& b : s.film.box_sums()) {
        b.sum.r = in.f32();
        b.sum.g = in.f32();
        b.sum.b = in.f32();
        b.weight = in.f32();
    }
    for (PixelSum& p : s.film.sums()) {
        p.r = in.i128();
        p.g = in.i128();
        p.b = in.i128();
        p.weight = in.i128();
    }
    if (s.splats) {
        std::vector<std::int64_t> sums(s.splats->size());
        for (std::int64_t& v : sums) v = std::int64_t(in.u64());
        s.splats->set_sums(sums);
    }
    if (in.left() != 0) throw ResumeError(corrupt);
}

}  // namespace

RenderIdentity identify_render(const std::filesystem::path& scene_file,
                               std::span<const std::filesystem::path> files_read,
                               const RenderSettings& settings, const RenderOptions& options,
                               std::string_view glint_version, const RenderPart& part) {
    RenderIdentity id;
    id.glint_version = glint_version;
    id.scene_path = std::filesystem::absolute(scene_file).lexically_normal().string();
    id.files.push_back(stamp_file(id.scene_path));
    for (const std::filesystem::path& file : files_read) id.files.push_back(stamp_file(file));
    id.width = settings.width;
    id.height = settings.height;
    id.samples_per_pixel = settings.samples_per_pixel;
    id.seed = options.seed;
    id.integrator = settings.integrator;
    id.sampler = sampler_of(settings);
    id.filter = filter_of(settings);
    id.max_depth = settings.max_depth;
    id.adaptive = settings.adaptive;
    id.tile_size = options.tile_size;
    id.pass_size = pass_size_of(settings, options);
    id.working_space = settings.working_space;
    id.part = part;
    return id;
}

RenderSettings settings_of(const RenderIdentity& id) {
    RenderSettings settings;
    settings.width = id.width;
    settings.height = id.height;
    settings.samples_per_pixel = id.samples_per_pixel;
    settings.integrator = id.integrator;
    settings.sampler = id.sampler;
    settings.filter = id.filter;
    settings.max_depth = id.max_depth;
    settings.adaptive = id.adaptive;
    settings.working_space = id.working_space;
    return settings;
}

std::filesystem::path resume_path(const std::filesystem::path& output) {
    std::filesystem::path path = output;
    path += ".resume";
    return path;
}

void write_resume_file(const std::filesystem::path& file, const RenderIdentity& identity,
                       const RenderState& state) {
    ByteWriter header;
    write_identity(header, identity);
    header.u64(encoded_size(state));
    // The packed size and CRC are known once the state is written: written then, here.
    const long sums_at = long(header.bytes().size());
    header.u64(0);
    header.u32(0);
    write_file_atomically(file, [&](const std::filesystem::path& temporary) {
        UniqueFile f = open_file(temporary, "wb");
        write_bytes(f.get(), header.bytes().data(), header.bytes().size(), temporary);
        DeflateToFile packed(f.get(), temporary);
        ByteWriter payload([&](const std::string& piece) { packed.add(piece); });
        encode_state(state, payload);
        payload.flush();
        packed.finish();
        assert(packed.given() == encoded_size(state));
        ByteWriter sums;
        sums.u64(packed.packed_size());
        sums.u32(packed.crc());
        if (std::fseek(f.get(), sums_at, SEEK_SET) != 0)
            throw ImageError(temporary, "cannot seek in the file being written");
        write_bytes(f.get(), sums.bytes().data(), sums.bytes().size(), temporary);
        close_written_file(std::move(f), temporary);
    });
}

namespace {

// The identity and state saved in `file`, which must have been written for `expected` if
// given, with `settings`' image; else for the settings its identity names.
SavedRender read_state_file(const std::filesystem::path& file, const std::string& prefix,
                            const RenderIdentity* expected, const RenderSettings* settings) {
    std::error_code error;
    if (!std::filesystem::exists(file, error))
        throw ResumeError(prefix + "there is no such file" +
                          (expected ? " (an interrupted render leaves it beside its output)" : ""));
    std::vector<unsigned char> bytes;
    try {
        bytes = read_whole_file(file);
    } catch (const ImageError& e) {
        throw ResumeError(prefix + e.detail);
    }
    const std::string truncated = prefix + "the file is truncated";
    const std::string corrupt = prefix + "the file is corrupt";
    ByteReader<ResumeError> in(bytes.data(), bytes.size(), truncated);
    if (bytes.size() < sizeof kMagic || std::memcmp(in.take(sizeof kMagic), kMagic, 8) != 0)
        throw ResumeError(
            prefix + (expected ? "not a glint resume file" : "not a glint part or resume file"));
    if (const std::uint32_t version = in.u32(); version != kFormatVersion)
        throw ResumeError(prefix + "the file is of format version " + std::to_string(version) +
                          ", this glint reads version " + std::to_string(kFormatVersion));
    RenderIdentity written = read_identity(in);
    if (expected)
        if (const std::string why = identity_difference(written, *expected); !why.empty())
            throw ResumeError(prefix + "the resume file was " + why);
    // Without a render to compare with, the identity itself must describe one.
    const RenderSettings own = settings_of(written);
    if (!settings) {
        if (written.width < 1 || written.height < 1 || written.width > kMaxImageSide ||
            written.height > kMaxImageSide || written.tile_size < 1 || written.pass_size < 1 ||
            written.samples_per_pixel < 1 || !describe_problem(written.filter).empty() ||
            std::size_t(written.integrator) >= integrator_names().size() ||
            written.part.count < 1 || written.part.index < 1 ||
            written.part.index > written.part.count ||
            std::size_t(written.part.split) >= std::size(kPartSplitNames) ||
            // At least 4 bytes a pixel, which deflate packs at most about 1000 to 1: a damaged
            // header cannot ask for the memory of a larger image than the file can hold.
            std::uint64_t(written.width) * std::uint64_t(written.height) * 4 >
                std::uint64_t(in.left()) * 1100)
            throw ResumeError(corrupt);
        settings = &own;
    }
    RenderState state(*settings, written.tile_size, written.pass_size);
    const std::uint64_t payload_size = in.u64(), packed_size = in.u64();
    const std::uint32_t crc = in.u32();
    // The size a state of this image has, so that a damaged header cannot ask for any memory.
    const std::uint64_t expected_size = encoded_size(state);
    if (payload_size != expected_size) throw ResumeError(corrupt);
    if (packed_size > in.left()) throw ResumeError(truncated);
    if (packed_size < in.left()) throw ResumeError(corrupt);
    std::vector<unsigned char> payload(payload_size);
    uLongf unpacked = uLongf(payload_size);
    if (uncompress(payload.data(), &unpacked, in.take(packed_size), uLong(packed_size)) != Z_OK ||
        unpacked != payload_size || crc32(0, payload.data(), uInt(payload.size())) != crc)
        throw ResumeError(corrupt);
    ByteReader<ResumeError> state_in(payload.data(), payload.size(), corrupt);
    decode_state(state_in, state, corrupt);
    const int passes = pass_count(settings->samples_per_pixel, state.pass_size);
    for (const int done : state.tile_passes)
        if (done < 0 || done > passes) throw ResumeError(corrupt);
    return {std::move(written), std::move(state)};
}

}  // namespace

RenderState read_resume_file(const std::filesystem::path& file, const RenderIdentity& expected,
                             const RenderSettings& settings) {
    return read_state_file(file, "cannot resume from \"" + file.string() + "\": ", &expected,
                           &settings)
        .state;
}

SavedRender read_saved_render(const std::filesystem::path& file) {
    return read_state_file(file, "cannot read \"" + file.string() + "\": ", nullptr, nullptr);
}

}  // namespace glint
