// How far apart two images are, for golden-image tests. Differences are measured on
// sRGB-encoded values in [0, 1] (what a viewer shows, linear values clamped first), so an
// error in the shadows weighs as much as the eye says it does.
#pragma once

#include <string>

#include "glint/image/image.h"

namespace glint {

struct ImageDifference {
    double rmse = 0;                     // root mean square over every channel of every pixel
    double max_abs = 0;                  // largest absolute channel difference
    double fraction_over_threshold = 0;  // of pixels with any channel differing by > threshold
    int width = 0, height = 0;
    double threshold = 0;  // the threshold fraction_over_threshold was counted with
};

// Compares channel by channel. A NaN against a number differs by 1 (the most there is), NaN
// against NaN by 0: a render that starts producing NaNs must fail its golden test. Images of
// different sizes are not comparable: throws ImageError saying both sizes.
ImageDifference compare_images(const Image& a, const Image& b, double threshold = 2.0 / 255);

// Per channel |a - b| in sRGB-encoded terms, times 4 and clamped to 1, stored so that writing
// it as PNG shows exactly that (black where equal). For saving next to a failing test's output.
// Throws ImageError if the sizes differ.
Image difference_image(const Image& a, const Image& b);

// One line for a test failure, e.g. "64x48 pixels: rmse 0.0012 (0.31/255), max 0.0431
// (11.0/255), 0.26% of pixels (8) differ by more than 0.0078 (2.0/255)".
std::string describe(const ImageDifference& difference);

}  // namespace glint
