// OpenEXR reading and writing. OpenEXR reports failures with its own exceptions (Iex, derived
// from std::exception); they are caught here and rethrown as ImageError naming the file.
#include "glint/image/exr_io.h"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfTileDescription.h>
#include <ImfVersion.h>
#include <ImfXdr.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>

#include "glint/image/image_error.h"
#include "glint/image/image_limits.h"

namespace glint {
namespace {

// The frame buffers below address the channels of Image::pixels in place.
static_assert(sizeof(Color) == 3 * sizeof(float) && offsetof(Color, g) == sizeof(float) &&
              offsetof(Color, b) == 2 * sizeof(float));

constexpr const char* kChannels[3] = {"R", "G", "B"};

// The attribute, if any, of the file's headers whose value claims more bytes than the file has
// left: OpenEXR allocates a value of an unknown type at its claimed size before reading it
// (1.8 GB for a 108-byte file). An attribute is a name and a type, each ended by a NUL, a 32-bit
// size and the value; an empty name ends a header, and an empty header the list of a multi-part
// file's. Damage of any other kind is left to OpenEXR, which reports it.
std::optional<std::string> exr_attribute_overrun(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const auto file_size = std::filesystem::file_size(path, ec);
    if (!in || ec) return std::nullopt;
    unsigned char start[8];
    if (!in.read(reinterpret_cast<char*>(start), 8) ||
        !Imf::isImfMagic(reinterpret_cast<char*>(start)))
        return std::nullopt;
    const bool multi_part = (start[5] & 0x10) != 0;  // version flags, bit 12
    const auto text = [&](std::string& s) {          // a NUL-ended string of at most 255 bytes
        s.clear();
        for (char c; in.get(c);) {
            if (c == '\0') return true;
            if (s.size() == 255) return false;
            s += c;
        }
        return false;
    };
    for (bool first = true;; first = false) {
        std::string name, type;
        if (!text(name)) return std::nullopt;
        if (name.empty()) {  // the end of a header: the next one's first name, or the end
            if (!multi_part || first) return std::nullopt;
            if (!text(name) || name.empty()) return std::nullopt;
        }
        unsigned char size_bytes[4];
        if (!text(type) || !in.read(reinterpret_cast<char*>(size_bytes), 4)) return std::nullopt;
        const std::int64_t size =
            std::int32_t(std::uint32_t(size_bytes[0]) | std::uint32_t(size_bytes[1]) << 8 |
                         std::uint32_t(size_bytes[2]) << 16 | std::uint32_t(size_bytes[3]) << 24);
        const auto at = std::int64_t(in.tellg());
        if (size < 0 || size > std::int64_t(file_size) - at)
            return "an attribute claims " + std::to_string(size) + " bytes, more than the " +
                   std::to_string(std::int64_t(file_size) - at) + " the file has left";
        in.seekg(size, std::ios::cur);
    }
}

// The fewest bytes a file with this header takes: its table of chunk offsets (8 bytes a tile or
// block of scanlines), or its pixels at the most its compression can pack them, for those whose
// most is known: one half-float channel of 2 bytes a pixel, by 1 uncompressed, 64 under RLE
// (2 bytes a run of 128), 11 under B44 (3 bytes a 4 x 4 block of 32) and 2064 under zlib (1032 to
// 1, and PXR24's 24-bit floats). PIZ and DWA are bounded by their table alone.
std::int64_t least_exr_bytes(const Imf::Header& header, std::int64_t width, std::int64_t height) {
    if (header.hasTileDescription()) {
        const Imf::TileDescription& tile = header.tileDescription();
        const std::int64_t x = std::max<std::int64_t>(1, tile.xSize),
                           y = std::max<std::int64_t>(1, tile.ySize);
        return 8 * ((width + x - 1) / x) * ((height + y - 1) / y);
    }
    const std::int64_t half_bytes = 2 * width * height;
    switch (header.compression()) {
        case Imf::NO_COMPRESSION:
            return half_bytes;
        case Imf::RLE_COMPRESSION:
            return half_bytes / 64;
        case Imf::B44_COMPRESSION:
        case Imf::B44A_COMPRESSION:
            return half_bytes / 11;
        case Imf::ZIPS_COMPRESSION:
        case Imf::ZIP_COMPRESSION:
        case Imf::PXR24_COMPRESSION:
            return half_bytes / 2064;
        default:
            return 8 * ((height + 255) / 256);
    }
}

// The first part's header, read alone: Imf::InputFile's constructor allocates line and tile
// buffers as large as the header claims, before glint could refuse an absurd size. Files whose
// header does not parse are left to InputFile, which says what is wrong with them.
void check_exr_header(const std::filesystem::path& path) {
    if (const auto overrun = exr_attribute_overrun(path))
        throw ImageError(path, "corrupt EXR header: " + *overrun);
    Imf::Header header;
    try {
        Imf::StdIFStream stream(path.c_str());
        char magic[4];
        stream.read(magic, 4);
        if (!Imf::isImfMagic(magic)) return;
        int version = 0;
        Imf::Xdr::read<Imf::StreamIO>(stream, version);
        header.readFrom(stream, version);
        header.sanityCheck(Imf::isTiled(version));
    } catch (const std::exception&) {
        return;
    }
    const Imath::Box2i window = header.dataWindow();
    const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1,
                       height = std::int64_t(window.max.y) - window.min.y + 1;
    check_image_size(path, width, height);
    // Before the pixels are allocated: 351 bytes claimed 151 million pixels (found by fuzzing).
    std::error_code ec;
    const auto file_size = std::filesystem::file_size(path, ec);
    if (!ec && least_exr_bytes(header, width, height) > std::int64_t(file_size))
        throw ImageError(path, "the image data ends early (the file is truncated)");
    if (header.hasTileDescription()) {
        const Imf::TileDescription& tile = header.tileDescription();
        if (tile.xSize > std::uint64_t(kMaxImageDimension) ||
            tile.ySize > std::uint64_t(kMaxImageDimension) ||
            std::uint64_t(tile.xSize) * tile.ySize > std::uint64_t(kMaxImagePixels)) {
            throw ImageError(path, "tile size " + std::to_string(tile.xSize) + "x" +
                                       std::to_string(tile.ySize) +
                                       " is larger than glint accepts");
        }
    }
}

// An EXR file's bytes kept in memory, for a page to download.
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("memory") {}
    void write(const char c[], int n) override {
        if (position_ + std::uint64_t(n) > bytes.size()) bytes.resize(position_ + n);
        std::copy(c, c + n, bytes.begin() + std::ptrdiff_t(position_));
        position_ += std::uint64_t(n);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }

    std::string bytes;

private:
    std::uint64_t position_ = 0;
};

// Writes the image and its layers into `path`, or into `memory` when it is given.
void write_exr_into(const std::filesystem::path& path, MemoryStream* memory, const Image& image,
                    std::span<const ExrLayer> layers) {
    check_image_shape(path, image);
    for (const ExrLayer& layer : layers) {
        if (layer.image->width != image.width || layer.image->height != image.height ||
            layer.channels.empty() || layer.channels.size() > 3)
            throw ImageError(path, "layer " + layer.name + " does not fit the image");
    }
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        // OpenEXR's slices take a non-const pointer for reading and writing alike; writing
        // only reads through it.
        const auto add = [&](const std::string& name, const Image& from, int c) {
            char* base = reinterpret_cast<char*>(const_cast<Color*>(from.pixels.data()));
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            frame.insert(name, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(Color),
                                          sizeof(Color) * std::size_t(from.width)));
        };
        for (int c = 0; c < 3; ++c) add(kChannels[c], image, c);
        for (const ExrLayer& layer : layers)
            for (std::size_t c = 0; c < layer.channels.size(); ++c)
                add(layer.name + "." + layer.channels[c], *layer.image, int(c));
        std::optional<Imf::OutputFile> file;
        if (memory)
            file.emplace(*memory, header);
        else
            file.emplace(path.c_str(), header);
        file->setFrameBuffer(frame);
        file->writePixels(image.height);
    } catch (const std::exception& e) {
        throw ImageError(path, std::string("cannot write EXR: ") + e.what());
    }
}

}  // namespace

void write_exr(const std::filesystem::path& path, const Image& image,
               std::span<const ExrLayer> layers) {
    write_exr_into(path, nullptr, image, layers);
}

std::string exr_bytes(const Image& image, std::span<const ExrLayer> layers) {
    MemoryStream memory;
    write_exr_into("image.exr", &memory, image, layers);
    return std::move(memory.bytes);
}

Image read_exr(const std::filesystem::path& path) {
    try {
        check_exr_header(path);
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
        const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
        check_image_size(path, width, height);

        Image image(static_cast<int>(width), static_cast<int>(height));
        Imf::FrameBuffer frame;
        for (int c = 0; c < 3; ++c) {
            // Slice::Make offsets the base by the data window's origin without overflow.
            frame.insert(kChannels[c],
                         Imf::Slice::Make(Imf::FLOAT, &image.pixels[0].r + c, window, sizeof(Color),
                                          sizeof(Color) * std::size_t(width), 1, 1,
                                          /*fillValue=*/0.0));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        throw ImageError(path, std::string("cannot read EXR: ") + e.what());
    }
}

}  // namespace glint
