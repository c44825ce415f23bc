// Dispatch from file extension to the format readers and writers.
#include "glint/image/image_io.h"

#include <string>

#include "glint/image/atomic_file.h"
#include "glint/image/exr_io.h"
#include "glint/image/image_error.h"
#include "glint/image/image_format.h"
#include "glint/image/image_limits.h"
#include "glint/image/pfm_io.h"
#include "glint/image/png_io.h"
#include "glint/image/ppm_io.h"

namespace glint {
namespace {

ImageFormat format_or_throw(const std::filesystem::path& path) {
    if (const auto format = format_from_extension(path)) return *format;
    const std::string known = std::string(known_image_extensions());
    if (!path.has_extension()) {
        throw ImageError(path,
                         "no file extension to tell the image format; known formats are " + known);
    }
    throw ImageError(path, "unknown image format \"" + path.extension().string() +
                               "\"; known formats are " + known);
}

}  // namespace

void write_image(const std::filesystem::path& path, const Image& image,
                 const WriteOptions& options) {
    const ImageFormat format = format_or_throw(path);
    check_image_shape(path, image);  // before a temporary file exists
    if (format != ImageFormat::exr && !options.exr_layers.empty())
        throw ImageError(path, "only an EXR file holds layers beside the image");
    write_file_atomically(path, [&](const std::filesystem::path& temporary) {
        switch (format) {
            case ImageFormat::png:
                return write_png(temporary, image);
            case ImageFormat::ppm:
                return write_ppm(temporary, image,
                                 options.ppm_ascii ? PpmEncoding::ascii : PpmEncoding::binary);
            case ImageFormat::pfm:
                return write_pfm(temporary, image);
            case ImageFormat::exr:
                return write_exr(temporary, image, options.exr_layers);
        }
    });
}

Image read_image(const std::filesystem::path& path) {
    switch (format_or_throw(path)) {
        case ImageFormat::png:
            return read_png(path);
        case ImageFormat::ppm:
            return read_ppm(path);
        case ImageFormat::pfm:
            return read_pfm(path);
        case ImageFormat::exr:
            return read_exr(path);
    }
    throw ImageError(path, "unhandled image format");  // unreachable: the switch is complete
}

}  // namespace glint
