#include "glint/render/film/aov_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "glint/image/bitmap_font.h"
#include "glint/image/colour_map.h"
#include "glint/image/srgb.h"

namespace glint {

namespace {

constexpr Color kStrip{0.004f, 0.004f, 0.004f};
constexpr Color kInk{0.9f, 0.9f, 0.9f};

std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", double(v));
    return text;
}

// A picture value given as it should appear in the 8-bit file: (n + 1) / 2 shows as that.
Color encoded(float r, float g, float b) {
    const auto linear = [](float e) { return srgb_to_linear(std::clamp(e, 0.0f, 1.0f)); };
    return {linear(r), linear(g), linear(b)};
}

// Pixels where a surface variable has no sample that hit: all its channels 0.
bool empty_pixel(const AovImage& layer, const Color& c) {
    return aov_info(layer.aov).kind == AovKind::surface && c.r == 0 && c.g == 0 && c.b == 0;
}

struct Range {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    void add(float v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    bool empty() const { return lo > hi; }
    // Over more than a decade of positive values (depths out to a horizon) the map is
    // logarithmic, so the near ones are told apart too.
    bool logarithmic() const { return lo > 0 && hi > 10 * lo; }
    float t(float v) const {
        if (!(hi > lo)) return 0.5f;
        if (logarithmic()) return std::log(std::max(v, lo) / lo) / std::log(hi / lo);
        return (v - lo) / (hi - lo);
    }
};

// The range of a scalar's finite values between its 1st and 99th percentiles: a few far values
// (a plane's depth towards the horizon) would leave every other pixel one colour.
Range percentile_range(std::vector<float> values) {
    Range r;
    if (values.empty()) return r;
    const auto at = [&](double q) {
        const auto k = std::size_t(q * double(values.size() - 1));
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
        return values[k];
    };
    r.add(at(0.01));
    r.add(at(0.99));
    return r;
}

// The legend: the strip's height for an image this wide, and its text scale.
int text_scale(int width) { return width >= 400 ? 2 : 1; }
int strip_height(int width) { return kGlyphHeight * text_scale(width) + 6; }

}  // namespace

Image aov_picture(const AovImage& layer) {
    const Image& in = layer.image;
    const AovInfo& info = aov_info(layer.aov);
    const int scale = text_scale(in.width), strip = strip_height(in.width);
    Image out(in.width, in.height + strip);
    std::fill(out.pixels.begin(), out.pixels.end(), kStrip);
    const auto pixel_count = in.pixels.size();
    std::string legend = std::string(info.name);
    Range range;  // of a scalar, for the colour bar

    if (info.kind == AovKind::id) {
        std::set<std::int32_t> ids;
        for (std::size_t i = 0; i < pixel_count; ++i) {
            const auto id = std::int32_t(in.pixels[i].r);
            out.pixels[i] = id_colour(id);
            if (id >= 0) ids.insert(id);
        }
        legend += " ids: " + std::to_string(ids.size()) + ", black for none";
    } else if (info.channels == 1) {
        std::vector<float> values;
        for (const Color& c : in.pixels)
            if (!empty_pixel(layer, c) && std::isfinite(c.r)) values.push_back(c.r);
        range = percentile_range(std::move(values));
        if (range.logarithmic()) legend += " (log)";
        for (std::size_t i = 0; i < pixel_count; ++i)
            out.pixels[i] = empty_pixel(layer, in.pixels[i]) || !std::isfinite(in.pixels[i].r)
                                ? Color{}
                                : colour_map(range.t(in.pixels[i].r));
    } else if (layer.aov == Aov::normal) {
        for (std::size_t i = 0; i < pixel_count; ++i) {
            const Color& n = in.pixels[i];
            out.pixels[i] = empty_pixel(layer, n)
                                ? Color{}
                                : encoded((n.r + 1) / 2, (n.g + 1) / 2, (n.b + 1) / 2);
        }
        legend += ": rgb = (xyz + 1) / 2";
    } else if (layer.aov == Aov::position) {
        Range axes[3];
        for (const Color& p : in.pixels)
            if (!empty_pixel(layer, p)) {
                axes[0].add(p.r);
                axes[1].add(p.g);
                axes[2].add(p.b);
            }
        for (std::size_t i = 0; i < pixel_count; ++i) {
            const Color& p = in.pixels[i];
            out.pixels[i] = empty_pixel(layer, p)
                                ? Color{}
                                : encoded(axes[0].t(p.r), axes[1].t(p.g), axes[2].t(p.b));
        }
        legend += ": rgb = xyz from (";
        for (int a = 0; a < 3; ++a) legend += (a ? "," : "") + number(axes[a].lo);
        legend += ") to (";
        for (int a = 0; a < 3; ++a) legend += (a ? "," : "") + number(axes[a].hi);
        legend += ")";
    } else if (layer.aov == Aov::uv) {
        const auto fraction = [](float x) { return std::isfinite(x) ? x - std::floor(x) : 0; };
        for (std::size_t i = 0; i < pixel_count; ++i) {
            const Color& uv = in.pixels[i];
            out.pixels[i] =
                empty_pixel(layer, uv) ? Color{} : encoded(fraction(uv.r), fraction(uv.g), 0);
        }
        legend += ": r = u, g = v (their fractions)";
    } else {  // a colour: the albedo, or a part of the image, shown as the image is
        std::copy(in.pixels.begin(), in.pixels.end(), out.pixels.begin());
        legend += ": " + std::string(info.description);
    }

    const int y = in.height + 3;
    draw_text(out, 3, y, legend, kInk, scale);
    if (info.channels == 1 && info.kind != AovKind::id) {
        // name, low, a bar of the map, high (the 1st and 99th percentiles)
        const std::string lo = range.empty() ? "none" : number(range.lo);
        const std::string hi = range.empty() ? "" : number(range.hi);
        int x = 3 + text_width(legend, scale) + 3 * scale * 2;
        draw_text(out, x, y, lo, kInk, scale);
        x += text_width(lo, scale) + 2 * scale;
        const int bar_end = in.width - 3 - text_width(hi, scale) - 2 * scale;
        for (int bx = x; bx < bar_end; ++bx) {
            const Color c = colour_map(float(bx - x) / float(std::max(1, bar_end - 1 - x)));
            for (int by = y; by < y + kGlyphHeight * scale; ++by) out.at(bx, by) = c;
        }
        draw_text(out, std::max(x, bar_end) + 2 * scale, y, hi, kInk, scale);
    }
    return out;
}

std::vector<ExrLayer> aov_exr_layers(std::span<const AovImage> layers) {
    std::vector<ExrLayer> out;
    for (const AovImage& layer : layers) {
        const AovInfo& info = aov_info(layer.aov);
        ExrLayer e{std::string(info.name), {}, &layer.image};
        for (int c = 0; c < info.channels; ++c)
            e.channels.emplace_back(info.channel[std::size_t(c)]);
        out.push_back(std::move(e));
    }
    return out;
}

}  // namespace glint
