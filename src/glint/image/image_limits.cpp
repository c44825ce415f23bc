// Size checks shared by every reader and writer.
#include "glint/image/image_limits.h"

#include <string>

#include "glint/image/image_error.h"

namespace glint {

void check_image_size(const std::filesystem::path& file, std::int64_t width, std::int64_t height,
                      std::int64_t max_pixels) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) {
        throw ImageError(file, "image size " + size + " is empty or negative");
    }
    if (width > kMaxImageDimension || height > kMaxImageDimension || width * height > max_pixels) {
        throw ImageError(file, "image size " + size + " is larger than glint accepts (at most " +
                                   std::to_string(kMaxImageDimension) + " pixels a side and " +
                                   std::to_string(max_pixels) + " pixels in all)");
    }
}

void check_image_shape(const std::filesystem::path& file, const Image& image) {
    check_image_size(file, image.width, image.height, kMaxWrittenImagePixels);
    const auto expected = std::size_t(image.width) * std::size_t(image.height);
    if (image.pixels.size() != expected) {
        throw ImageError(file, "image claims " + std::to_string(image.width) + "x" +
                                   std::to_string(image.height) + " pixels but holds " +
                                   std::to_string(image.pixels.size()));
    }
}

}  // namespace glint
