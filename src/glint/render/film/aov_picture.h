// Output variables written as files: as layers of the image's EXR file, or each as a PNG a reader
// can look at, its numbers turned to colours (a colour map for scalars, distinct colours for ids)
// with a legend in a strip below that says how.
#pragma once

#include <span>
#include <vector>

#include "glint/image/exr_io.h"
#include "glint/image/image.h"
#include "glint/render/film/aov_films.h"

namespace glint {

// The PNG's picture of one variable: the layer's size plus the legend's strip below it.
Image aov_picture(const AovImage& layer);

// The layers for write_exr, named and with channels as aov_info gives them; they point into
// `layers`, which must outlive them.
std::vector<ExrLayer> aov_exr_layers(std::span<const AovImage> layers);

}  // namespace glint
