// Reading NFF's view entity: six lines in a fixed order, each checked where it is written, then
// checked as a whole (a direction to look in, an up that is not along it).
#include "glint/scene/nff/nff_view.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "glint/scene/scene.h"
#include "glint/scene/suggest.h"

namespace glint {

NffView read_nff_view(NffTokenizer& tokens, const NffToken& keyword, std::int64_t max_pixels) {
    const auto point = [&](const NffEntity& e, const char* x, const char* y, const char* z) {
        const float px = tokens.number(e, {x});
        const float py = tokens.number(e, {y});
        return Point3{px, py, tokens.number(e, {z})};
    };
    const NffEntity e{"view", keyword};
    NffView v;
    v.location = keyword.location();
    NffToken lines[6];
    for (std::size_t i = 0; i < 6; ++i) {
        const std::string expected(kNffViewLines[i]);
        const NffToken line = tokens.next();
        if (line.at_end()) {
            throw tokens.error_at_end("the file ends inside the view that starts at line " +
                                          std::to_string(keyword.line) + ": expected its \"" +
                                          expected + "\" line",
                                      {kNffViewOrder});
        }
        if (line.text != kNffViewLines[i]) {
            const auto* found = std::find(kNffViewLines.begin(), kNffViewLines.end(), line.text);
            if (found != kNffViewLines.end() && found > kNffViewLines.begin() + i) {
                throw tokens.error_at(line,
                                      "the view is missing its \"" + expected +
                                          "\" line: expected it before " + quote(line.text),
                                      {kNffViewOrder});
            }
            if (found != kNffViewLines.end()) {
                throw tokens.error_at(line,
                                      "view line " + quote(line.text) +
                                          " is out of order: expected \"" + expected + "\" here",
                                      {kNffViewOrder});
            }
            throw tokens.error_at(
                line, "expected the view's \"" + expected + "\" line, got " + quote(line.text),
                {kNffViewOrder + did_you_mean(line.text, kNffViewLines)});
        }
        lines[i] = line;
        switch (i) {
            case 0:
                v.from = point(e, "from x", "from y", "from z");
                break;
            case 1:
                v.at = point(e, "at x", "at y", "at z");
                break;
            case 2:
                v.up = to_vector(point(e, "up x", "up y", "up z"));
                break;
            case 3: {
                const NffToken angle = tokens.require(e, {"angle"});
                v.angle_degrees = tokens.number_of(angle, e, {"angle"});
                if (!(v.angle_degrees > 0 && v.angle_degrees < 180)) {
                    throw tokens.error_at(angle,
                                          "the view's angle must be between 0 and 180 degrees, "
                                          "got " +
                                              std::string(angle.text));
                }
                break;
            }
            case 4:
                v.hither = tokens.number(e, {"hither"});
                break;
            default: {
                const NffToken w = tokens.require(e, {"resolution width"});
                const std::int64_t width = tokens.integer_of(w, e, {"resolution width"});
                const NffToken h = tokens.require(e, {"resolution height"});
                const std::int64_t height = tokens.integer_of(h, e, {"resolution height"});
                for (const auto& [token, value, what] :
                     {std::tuple{w, width, "width"}, std::tuple{h, height, "height"}}) {
                    if (value < 1 || value > kMaxImageSide) {
                        throw tokens.error_at(token, std::string("the view's resolution ") + what +
                                                         " must be between 1 and " +
                                                         std::to_string(kMaxImageSide) + ", got " +
                                                         std::string(token.text));
                    }
                }
                if (width * height > max_pixels) {
                    throw tokens.error_at(h,
                                          "the view's resolution " + std::string(w.text) + " x " +
                                              std::string(h.text) +
                                              " has more pixels than the limit of " +
                                              std::to_string(max_pixels),
                                          {"raise the limit with --max-pixels N"});
                }
                v.width = int(width), v.height = int(height);
            }
        }
    }
    // A camera needs a direction to look in and an up that is not along it (in double: the
    // cross product of float vectors underflows for tiny scenes).
    const double dx = double(v.at.x) - v.from.x, dy = double(v.at.y) - v.from.y,
                 dz = double(v.at.z) - v.from.z;
    if (dx == 0 && dy == 0 && dz == 0) {
        throw tokens.error_at(lines[1],
                              "the view's at is the same point as its from: it looks nowhere");
    }
    const double cx = dy * v.up.z - dz * v.up.y, cy = dz * v.up.x - dx * v.up.z,
                 cz = dx * v.up.y - dy * v.up.x;
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double u =
        std::sqrt(double(v.up.x) * v.up.x + double(v.up.y) * v.up.y + double(v.up.z) * v.up.z);
    if (!(std::sqrt(cx * cx + cy * cy + cz * cz) > 1e-6 * d * u)) {
        throw tokens.error_at(lines[2],
                              "the view's up is zero or parallel to the viewing direction "
                              "(from \"from\" to \"at\"), so it does not say which way is up");
    }
    return v;
}

}  // namespace glint
