// Crease-angle vertex normals: per-corner averages of nearby face normals, then one vertex per
// distinct (vertex, normal) pair.
#include "glint/geometry/vertex_normals.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <span>

#include "glint/math/constants.h"
#include "glint/math/huge_page_allocator.h"

namespace glint {

namespace {

// Above this many corners around one position (a fan of thousands of triangles), the quadratic
// per-corner average is not worth its time: those corners get their face's normal.
constexpr std::size_t kMaxSmoothedValence = 1024;

Vector3 unit_or_zero(Vector3 v) {
    const float m = max_component(abs(v));
    if (!(m > 0) || !std::isfinite(m)) return {};
    return normalize(v / m);
}

// The interior angle of the triangle at corner a, from the unit edges towards b and c.
float corner_angle(Point3 a, Point3 b, Point3 c) {
    const Vector3 u = unit_or_zero(b - a), v = unit_or_zero(c - a);
    // atan2 of |u x v| and u.v is accurate for angles near 0 and pi, unlike acos.
    return std::atan2(length(cross(u, v)), dot(u, v));
}

// Compressed rows: for each key, the list of items with that key, in item order.
struct Groups {
    std::vector<std::uint32_t> start;  // key k's items are items[start[k] .. start[k + 1])
    std::vector<std::uint32_t> items;
};

Groups group_by(const std::vector<std::uint32_t>& key_of_item, std::size_t keys) {
    Groups g;
    g.start.assign(keys + 1, 0);
    for (const std::uint32_t k : key_of_item) ++g.start[k + 1];
    std::partial_sum(g.start.begin(), g.start.end(), g.start.begin());
    g.items.resize(key_of_item.size());
    std::vector<std::uint32_t> fill(g.start.begin(), g.start.end() - 1);
    for (std::uint32_t i = 0; i < key_of_item.size(); ++i) g.items[fill[key_of_item[i]]++] = i;
    return g;
}

// Ids that are equal exactly for vertices at the same position (bitwise, with -0 == 0).
std::vector<std::uint32_t> position_ids(std::span<const Point3> positions) {
    const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f == 0 ? 0.0f : f); };
    std::vector<std::uint32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto key = [&](std::uint32_t i) {
        const Point3 p = positions[i];
        return std::array<std::uint32_t, 3>{bits(p.x), bits(p.y), bits(p.z)};
    };
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> id(positions.size());
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i > 0 && key(order[i]) != key(order[i - 1])) ++next;
        id[order[i]] = next;
    }
    return id;
}

}  // namespace

void compute_vertex_normals(MeshData& mesh, float crease_angle_degrees) {
    const std::size_t face_count = mesh.triangles.size();
    const std::size_t corner_count = 3 * face_count;
    std::vector<Vector3> face_normal(face_count);
    std::vector<float> angle(corner_count);
    for (std::size_t f = 0; f < face_count; ++f) {
        const auto& t = mesh.triangles[f];
        const Point3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        face_normal[f] = unit_or_zero(cross(b - a, c - a));
        angle[3 * f] = corner_angle(a, b, c);
        angle[3 * f + 1] = corner_angle(b, c, a);
        angle[3 * f + 2] = corner_angle(c, a, b);
    }

    // Corners around each distinct position.
    const std::vector<std::uint32_t> position_id = position_ids(mesh.positions);
    const std::size_t position_count =
        mesh.positions.empty()
            ? 0
            : std::size_t(*std::max_element(position_id.begin(), position_id.end())) + 1;
    std::vector<std::uint32_t> corner_position(corner_count);
    for (std::size_t c = 0; c < corner_count; ++c) {
        corner_position[c] = position_id[mesh.triangles[c / 3][c % 3]];
    }
    const Groups around = group_by(corner_position, position_count);

    // Faces count as smooth neighbours when their normals' angle is below the crease angle.
    const float cos_crease = std::cos(radians(std::clamp(crease_angle_degrees, 0.0f, 180.0f)));
    std::vector<Vector3> corner_normal(corner_count);
    for (std::size_t pos = 0; pos < position_count; ++pos) {
        const std::uint32_t* begin = around.items.data() + around.start[pos];
        const std::uint32_t* end = around.items.data() + around.start[pos + 1];
        const bool smooth = std::size_t(end - begin) <= kMaxSmoothedValence;
        for (const std::uint32_t* c = begin; c != end; ++c) {
            const Vector3 own = face_normal[*c / 3];
            Vector3 sum;
            if (smooth) {
                for (const std::uint32_t* o = begin; o != end; ++o) {
                    const Vector3 other = face_normal[*o / 3];
                    if (*o == *c || dot(own, other) > cos_crease) sum += other * angle[*o];
                }
            }
            const Vector3 n = unit_or_zero(sum);
            corner_normal[*c] = (n.x == 0 && n.y == 0 && n.z == 0) ? own : n;
        }
    }

    // One output vertex per distinct (input vertex, normal) pair, in order of first use.
    std::vector<std::uint32_t> corner_vertex(corner_count);
    for (std::size_t c = 0; c < corner_count; ++c) corner_vertex[c] = mesh.triangles[c / 3][c % 3];
    const Groups uses = group_by(corner_vertex, mesh.positions.size());
    LargeVector<Point3> positions;
    LargeVector<Normal3> normals;
    LargeVector<Point2> uvs;
    std::vector<std::uint32_t> new_index(corner_count);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const std::uint32_t first_new = std::uint32_t(positions.size());
        // The search for an equal normal is skipped around huge fans, where it would be
        // quadratic; those corners each get their own vertex.
        const bool share = uses.start[v + 1] - uses.start[v] <= kMaxSmoothedValence;
        for (std::uint32_t k = uses.start[v]; k < uses.start[v + 1]; ++k) {
            const std::uint32_t c = uses.items[k];
            const Normal3 n(corner_normal[c]);
            std::uint32_t found = share ? first_new : std::uint32_t(positions.size());
            while (found < positions.size() && !(normals[found] == n)) ++found;
            if (found == positions.size()) {
                positions.push_back(mesh.positions[v]);
                normals.push_back(n);
                if (!mesh.uvs.empty()) uvs.push_back(mesh.uvs[v]);
            }
            new_index[c] = found;
        }
    }
    for (std::size_t c = 0; c < corner_count; ++c) mesh.triangles[c / 3][c % 3] = new_index[c];
    mesh.positions = std::move(positions);
    mesh.normals = std::move(normals);
    mesh.uvs = std::move(uvs);
}

}  // namespace glint
