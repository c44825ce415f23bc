// PNG through libpng; libdeflate compresses the pixels written. libpng reports errors by longjmp:
// only the two small functions marked below call setjmp, and they hold nothing with a destructor,
// so a jump never skips C++ cleanup. Everything that owns memory lives in their callers.
#include "glint/image/png_io.h"

#include <libdeflate.h>
#include <png.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "glint/image/file_io.h"
#include "glint/image/image_error.h"
#include "glint/image/image_limits.h"
#include "glint/image/quantize.h"
#include "glint/image/srgb.h"

namespace glint {
namespace {

// Where the error callback leaves libpng's message; plain data, as it outlives the jump.
struct PngMessage {
    char text[256] = "unknown libpng error";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
    auto* out = static_cast<PngMessage*>(png_get_error_ptr(png));
    std::snprintf(out->text, sizeof out->text, "%s", message);
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}  // e.g. unknown chunks: not the user's problem

struct PngWriteStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngWriteStructs() { png_destroy_write_struct(&png, &info); }
};

struct PngReadStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngReadStructs() { png_destroy_read_struct(&png, &info, nullptr); }
};

// The PNG's scanlines: each row of quantize_srgb8's bytes behind its filter type, Sub (each byte
// less the byte of the pixel to its left). For dithered renders one filter for every row makes
// files as small as libpng's choice of the best filter for each row, without trying five a row.
std::vector<std::uint8_t> sub_filtered_scanlines(const Image& image) {
    const std::size_t row_bytes = std::size_t(image.width) * 3;
    std::vector<std::uint8_t> out(std::size_t(image.height) * (row_bytes + 1));
    tbb::parallel_for(0, image.height, [&](int y) {
        std::uint8_t* line = out.data() + std::size_t(y) * (row_bytes + 1);
        line[0] = 1;  // Sub
        std::uint8_t* row = line + 1;
        quantize_srgb8_row(image, y, row);
        for (std::size_t i = row_bytes; i-- > 3;) row[i] = std::uint8_t(row[i] - row[i - 3]);
    });
    return out;
}

// The scanlines as one zlib stream, the image data of the IDAT chunks. libdeflate's fastest
// level writes smaller files than zlib's fastest and takes a third of its time.
std::vector<std::uint8_t> compressed(const std::vector<std::uint8_t>& scanlines, PngDeflate deflate,
                                     const std::filesystem::path& name) {
    struct Compressor {
        libdeflate_compressor* c;
        ~Compressor() { libdeflate_free_compressor(c); }
    } compressor{libdeflate_alloc_compressor(deflate == PngDeflate::stored ? 0 : 1)};
    if (!compressor.c) throw ImageError(name, "cannot write PNG: out of memory");
    std::vector<std::uint8_t> out(libdeflate_zlib_compress_bound(compressor.c, scanlines.size()));
    out.resize(libdeflate_zlib_compress(compressor.c, scanlines.data(), scanlines.size(),
                                        out.data(), out.size()));
    if (out.empty()) throw ImageError(name, "cannot write PNG: compression failed");
    return out;
}

// Calls setjmp: plain locals only. libpng writes the chunks, CRCs included; the image data is
// already compressed, so it goes in as IDAT chunks of its own.
bool encode_png(png_structp png, png_infop info, png_uint_32 width, png_uint_32 height,
                const std::uint8_t* data, std::size_t size) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    constexpr std::size_t kIdatBytes = std::size_t(1) << 20;  // a chunk holds at most 2^31 - 1
    for (std::size_t at = 0; at < size; at += kIdatBytes)
        png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), data + at,
                        std::min(kIdatBytes, size - at));
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
    png_write_flush(png);
    return true;
}

// Where png_bytes() has libpng write: a string, which may fail to grow (no exception may cross
// libpng's C frames, so it is caught here and looked at afterwards).
struct MemoryWriter {
    std::string* out;
    bool failed = false;
};

void write_to_memory(png_structp png, png_bytep data, png_size_t count) {
    auto* writer = static_cast<MemoryWriter*>(png_get_io_ptr(png));
    if (writer->failed) return;
    try {
        writer->out->append(reinterpret_cast<const char*>(data), count);
    } catch (...) {
        writer->failed = true;
    }
}

void flush_memory(png_structp) {}

// Calls setjmp: plain locals only. Reads the header and asks libpng to deliver every PNG as
// 16-bit RGB in host byte order, so one decoding loop serves all colour types and depths.
bool read_png_header(png_structp png, png_infop info, std::FILE* file, png_uint_32* width,
                     png_uint_32* height) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, png_uint_32(kMaxImageDimension), png_uint_32(kMaxImageDimension));
    png_read_info(png, info);
    png_set_expand(png);  // palette to RGB, gray below 8 bits to 8 bits
    png_set_expand_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    if constexpr (std::endian::native == std::endian::little) png_set_swap(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    return true;
}

// Calls setjmp: plain locals only.
bool read_png_rows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

// libpng reading from memory: where the next byte is, and where the bytes end.
struct MemoryReader {
    std::span<const unsigned char> bytes;
    std::size_t at = 0;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t count) {
    auto* reader = static_cast<MemoryReader*>(png_get_io_ptr(png));
    if (count > reader->bytes.size() - reader->at) png_error(png, "file is truncated");
    std::memcpy(out, reader->bytes.data() + reader->at, count);
    reader->at += count;
}

// Calls setjmp: plain locals only. The header of a palette PNG, its indices unpacked to a byte
// each; false on error, and *palette false for another colour type.
bool read_palette_header(png_structp png, png_infop info, MemoryReader* reader, bool* palette,
                         png_uint_32* width, png_uint_32* height) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, reader, read_from_memory);
    png_set_user_limits(png, png_uint_32(kMaxImageDimension), png_uint_32(kMaxImageDimension));
    png_read_info(png, info);
    *palette = png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE;
    if (!*palette) return true;
    png_set_packing(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    return true;
}

float decode_srgb16(std::uint16_t value) {
    static const std::vector<float> table = [] {
        std::vector<float> t(65536);
        for (std::size_t i = 0; i < t.size(); ++i) t[i] = srgb_to_linear(float(i) / 65535);
        return t;
    }();
    return table[value];
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
    check_image_shape(path, image);
    const std::vector<std::uint8_t> data =
        compressed(sub_filtered_scanlines(image), PngDeflate::fast, path);

    UniqueFile file = open_file(path, "wb");
    PngMessage message;
    PngWriteStructs s;
    s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
    if (s.png) s.info = png_create_info_struct(s.png);
    if (!s.info) throw ImageError(path, "cannot write PNG: libpng could not start");
    png_init_io(s.png, file.get());
    errno = 0;
    if (!encode_png(s.png, s.info, png_uint_32(image.width), png_uint_32(image.height), data.data(),
                    data.size())) {
        // libpng says only "Write Error" when the file system refuses; the system says why.
        const int reason = errno;
        if (std::ferror(file.get()) && reason != 0)
            throw ImageError(path, std::string("write failed: ") + std::strerror(reason));
        throw ImageError(path, std::string("cannot write PNG: ") + message.text);
    }
    close_written_file(std::move(file), path);
}

std::string png_bytes(const Image& image, PngDeflate deflate) {
    const std::filesystem::path name("(an image in memory)");
    check_image_shape(name, image);
    const std::vector<std::uint8_t> data = compressed(sub_filtered_scanlines(image), deflate, name);
    std::string out;
    MemoryWriter writer{&out};
    PngMessage message;
    PngWriteStructs s;
    s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
    if (s.png) s.info = png_create_info_struct(s.png);
    if (!s.info) throw ImageError(name, "cannot write PNG: libpng could not start");
    png_set_write_fn(s.png, &writer, write_to_memory, flush_memory);
    if (!encode_png(s.png, s.info, png_uint_32(image.width), png_uint_32(image.height), data.data(),
                    data.size()))
        throw ImageError(name, std::string("cannot write PNG: ") + message.text);
    if (writer.failed) throw ImageError(name, "cannot write PNG: out of memory");
    return out;
}

std::optional<PaletteImage> read_png_palette(std::span<const unsigned char> bytes,
                                             const std::filesystem::path& name) {
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0) return std::nullopt;
    PngMessage message;
    PngReadStructs s;
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
    if (s.png) s.info = png_create_info_struct(s.png);
    if (!s.info) throw ImageError(name, "cannot read PNG: libpng could not start");
    MemoryReader reader{bytes};
    bool palette = false;
    png_uint_32 width = 0, height = 0;
    if (!read_palette_header(s.png, s.info, &reader, &palette, &width, &height))
        throw ImageError(name, std::string("malformed PNG: ") + message.text);
    if (!palette) return std::nullopt;
    check_image_size(name, width, height);
    if (png_get_rowbytes(s.png, s.info) != std::size_t(width))
        throw ImageError(name, "malformed PNG: unexpected row layout of palette indices");
    PaletteImage image{int(width), int(height),
                       std::vector<std::uint8_t>(std::size_t(width) * height)};
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = image.indices.data() + y * width;
    if (!read_png_rows(s.png, rows.data()))
        throw ImageError(name, std::string("malformed PNG: ") + message.text);
    return image;
}

Image read_png(const std::filesystem::path& path) {
    UniqueFile file = open_file(path, "rb");
    std::array<png_byte, 8> signature{};
    if (std::fread(signature.data(), 1, signature.size(), file.get()) != signature.size() ||
        png_sig_cmp(signature.data(), 0, signature.size()) != 0) {
        throw ImageError(path, "not a PNG file (wrong signature)");
    }

    PngMessage message;
    PngReadStructs s;
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
    if (s.png) s.info = png_create_info_struct(s.png);
    if (!s.info) throw ImageError(path, "cannot read PNG: libpng could not start");

    png_uint_32 width = 0, height = 0;
    if (!read_png_header(s.png, s.info, file.get(), &width, &height)) {
        throw ImageError(path, std::string("malformed PNG: ") + message.text);
    }
    check_image_size(path, width, height);
    if (png_get_rowbytes(s.png, s.info) != std::size_t(width) * 6) {
        throw ImageError(path, "malformed PNG: unexpected row layout after conversion to RGB");
    }

    std::vector<std::uint16_t> samples(std::size_t(width) * height * 3);
    std::vector<png_bytep> rows(height);
    for (std::size_t y = 0; y < rows.size(); ++y) {
        rows[y] = reinterpret_cast<png_bytep>(samples.data() + y * std::size_t(width) * 3);
    }
    if (!read_png_rows(s.png, rows.data())) {
        throw ImageError(path, std::string("malformed PNG: ") + message.text);
    }

    Image image(static_cast<int>(width), static_cast<int>(height));
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = {decode_srgb16(samples[3 * i]), decode_srgb16(samples[3 * i + 1]),
                           decode_srgb16(samples[3 * i + 2])};
    }
    return image;
}

}  // namespace glint
