// The exact area a region of the image covers in each pixel, and the centroid of that part:
// how a beam tree is drawn without aliasing at polygon edges. Each ring is clipped to a row of
// pixels and then to each pixel of the row (Sutherland-Hodgman against a convex window keeps
// the signed area of any ring, convex or not), and holes, of negative area, take theirs away.
#pragma once

#include <cstddef>
#include <vector>

#include "glint/render/beam/planar_region.h"

namespace glint::beam {

// Image coordinates are pixels times this, in Clipper's integers: vertices are placed to
// 1/65536 of a pixel.
inline constexpr double kSubpixel = 65536;

class CoverageGrid {
public:
    // For the pixels [x0, x1) x [y0, y1); parts of regions outside are not counted.
    CoverageGrid(int x0, int y0, int x1, int y1);

    // Adds the region's area to each pixel it covers.
    void add(const Paths& region);
    // Calls f(x, y, area, centroid_x, centroid_y) for each pixel with some area (in pixels,
    // centroid in film coordinates), then forgets them all.
    template <class F>
    void drain(F&& f) {
        for (std::size_t i : touched_) {
            Share& s = shares_[i];
            if (s.area > 1e-12) {
                const int x = x0_ + int(i % std::size_t(width_)),
                          y = y0_ + int(i / std::size_t(width_));
                f(x, y, s.area, s.mx / s.area, s.my / s.area);
            }
            s = {};
        }
        touched_.clear();
    }
    // The area counted so far in pixel (x, y) (inside the window), without forgetting it.
    double area_at(int x, int y) const {
        return shares_[std::size_t(y - y0_) * std::size_t(width_) + std::size_t(x - x0_)].area;
    }
    // Forgets every pixel's area.
    void clear() {
        drain([](int, int, double, double, double) {});
    }

private:
    struct Share {
        double area = 0, mx = 0, my = 0;  // area, and its first moments
        bool touched = false;
    };
    void add_ring(const Path& ring);

    int x0_, y0_, x1_, y1_, width_;
    std::vector<Share> shares_;
    std::vector<std::size_t> touched_;
    std::vector<double> row_, cell_, scratch_;  // clipped rings as x, y pairs
};

// The signed area of a ring clipped to the pixel square [x, x+1] x [y, y+1] (ring in pixels):
// for tests, against the grid.
double area_in_pixel(const std::vector<double>& ring_xy, int x, int y);

}  // namespace glint::beam
