// A pixel's running mean and variance of luminance (Welford), by which adaptive sampling decides
// that a pixel has enough samples. Plain data: a render's state keeps one a pixel across passes.
#pragma once

#include <algorithm>
#include <cmath>

#include "glint/math/color.h"
#include "glint/math/interval.h"
#include "glint/scene/scene.h"

namespace glint {

struct PixelError {
    int n = 0;  // samples added
    double mean = 0, m2 = 0;

    void add(Color c) {
        const double y = luminance(c);
        ++n;
        const double delta = y - mean;
        mean += delta / n;
        m2 += delta * (y - mean);
    }
    // 1.96 standard errors of the mean over max(mean, the dark level).
    double relative_error() const {
        if (n < 2) return kInfinity;
        const double standard_error = std::sqrt(m2 / (n - 1) / n);
        return 1.96 * standard_error / std::max(std::abs(mean), double(kAdaptiveDarkLevel));
    }
    bool operator==(const PixelError&) const = default;

private:
    static double luminance(Color c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
};

}  // namespace glint
