// An image of linear RGB floats, row by row from the top-left pixel.
#pragma once

#include <cstddef>
#include <vector>

#include "glint/math/color.h"

namespace glint {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;

    Image() = default;
    Image(int w, int h, Color fill = {}) : width(w), height(h), pixels(std::size_t(w) * h, fill) {}

    Color& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

}  // namespace glint
