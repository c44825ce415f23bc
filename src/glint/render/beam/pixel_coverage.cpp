// Rings clipped to rows, then to pixels, with their signed areas and first moments.
#include "glint/render/beam/pixel_coverage.h"

#include <algorithm>
#include <cmath>

namespace glint::beam {

namespace {

// Sutherland-Hodgman against one axis-aligned half-plane: coordinate `axis` (0: x, 1: y)
// >= value when keep_above, else <= value. Rings are flat x, y pairs.
void clip_ring(const std::vector<double>& in, int axis, double value, bool keep_above,
               std::vector<double>& out) {
    out.clear();
    const std::size_t n = in.size() / 2;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const double p = in[2 * i + std::size_t(axis)], q = in[2 * j + std::size_t(axis)];
        const bool p_in = keep_above ? p >= value : p <= value;
        const bool q_in = keep_above ? q >= value : q <= value;
        if (p_in) out.insert(out.end(), {in[2 * i], in[2 * i + 1]});
        if (p_in != q_in) {
            const double f = (value - p) / (q - p);
            out.push_back(in[2 * i] + f * (in[2 * j] - in[2 * i]));
            out.push_back(in[2 * i + 1] + f * (in[2 * j + 1] - in[2 * i + 1]));
            out[out.size() - 2 + std::size_t(axis)] = value;  // exactly on the line
        }
    }
}

// Signed area and first moments (the shoelace and its centroid sums) of a flat ring.
void area_moments(const std::vector<double>& ring, double& area, double& mx, double& my) {
    area = mx = my = 0;
    const std::size_t n = ring.size() / 2;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const double cr = ring[2 * i] * ring[2 * j + 1] - ring[2 * j] * ring[2 * i + 1];
        area += cr;
        mx += (ring[2 * i] + ring[2 * j]) * cr;
        my += (ring[2 * i + 1] + ring[2 * j + 1]) * cr;
    }
    area /= 2;
    mx /= 6;
    my /= 6;
}

}  // namespace

CoverageGrid::CoverageGrid(int x0, int y0, int x1, int y1)
    : x0_(x0),
      y0_(y0),
      x1_(x1),
      y1_(y1),
      width_(x1 - x0),
      shares_(std::size_t(x1 - x0) * std::size_t(y1 - y0)) {}

void CoverageGrid::add(const Paths& region) {
    for (const Path& ring : region) add_ring(ring);
}

void CoverageGrid::add_ring(const Path& ring) {
    if (ring.size() < 3) return;
    std::vector<double> xy;
    xy.reserve(2 * ring.size());
    double min_y = HUGE_VAL, max_y = -HUGE_VAL;
    for (const IntPoint& p : ring) {
        xy.push_back(double(p.X) / kSubpixel);
        xy.push_back(double(p.Y) / kSubpixel);
        min_y = std::min(min_y, xy.back()), max_y = std::max(max_y, xy.back());
    }
    const int row_begin = std::max(y0_, int(std::floor(min_y)));
    const int row_end = std::min(y1_, int(std::ceil(max_y)));
    for (int y = row_begin; y < row_end; ++y) {
        clip_ring(xy, 1, double(y), true, scratch_);
        clip_ring(scratch_, 1, double(y + 1), false, row_);
        if (row_.size() < 6) continue;
        double min_x = HUGE_VAL, max_x = -HUGE_VAL;
        for (std::size_t i = 0; i < row_.size(); i += 2)
            min_x = std::min(min_x, row_[i]), max_x = std::max(max_x, row_[i]);
        const int col_begin = std::max(x0_, int(std::floor(min_x)));
        const int col_end = std::min(x1_, int(std::ceil(max_x)));
        for (int x = col_begin; x < col_end; ++x) {
            clip_ring(row_, 0, double(x), true, scratch_);
            clip_ring(scratch_, 0, double(x + 1), false, cell_);
            if (cell_.size() < 6) continue;
            double area, mx, my;
            area_moments(cell_, area, mx, my);
            const std::size_t i = std::size_t(y - y0_) * std::size_t(width_) + std::size_t(x - x0_);
            Share& s = shares_[i];
            if (!s.touched) {
                s.touched = true;
                touched_.push_back(i);
            }
            s.area += area, s.mx += mx, s.my += my;
        }
    }
}

double area_in_pixel(const std::vector<double>& ring_xy, int x, int y) {
    std::vector<double> a, b;
    clip_ring(ring_xy, 1, double(y), true, a);
    clip_ring(a, 1, double(y + 1), false, b);
    clip_ring(b, 0, double(x), true, a);
    clip_ring(a, 0, double(x + 1), false, b);
    double area, mx, my;
    area_moments(b, area, mx, my);
    return area;
}

}  // namespace glint::beam
