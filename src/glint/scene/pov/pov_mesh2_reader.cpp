// POV-Ray's mesh2: its vertex, normal and uv arrays and the faces that index them, onto glint's
// triangle mesh. Where normals or uvs have indices of their own, each face gets corners of its
// own; otherwise the arrays are shared as they are.
#include <cmath>
#include <map>

#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

namespace {

using Faces = std::vector<std::array<std::uint32_t, 3>>;

struct Mesh2 {
    std::vector<Point3> vertices;
    std::vector<Normal3> normals;
    std::vector<Point2> uvs;
    Faces faces, normal_faces, uv_faces;
    std::vector<std::shared_ptr<const PovTexture>> textures;  // texture_list
    std::vector<std::int64_t> face_texture;                   // per face; -1: the object's
};

// The arrays of the faces `chosen` (indices into m.faces): shared as they are when normals and
// uvs have no indices of their own and every face is chosen, else three corners a face.
MeshData arrays_of(const Mesh2& m, const std::vector<std::size_t>& chosen) {
    MeshData arrays;
    if (m.normal_faces.empty() && m.uv_faces.empty() && chosen.size() == m.faces.size()) {
        arrays.positions.assign(m.vertices.begin(), m.vertices.end());
        if (m.normals.size() == m.vertices.size())
            arrays.normals.assign(m.normals.begin(), m.normals.end());
        if (m.uvs.size() == m.vertices.size()) arrays.uvs.assign(m.uvs.begin(), m.uvs.end());
        arrays.triangles.assign(m.faces.begin(), m.faces.end());
        return arrays;
    }
    const Faces& nf = m.normal_faces.empty() ? m.faces : m.normal_faces;
    const Faces& uf = m.uv_faces.empty() ? m.faces : m.uv_faces;
    const bool normals =
        !m.normals.empty() && (!m.normal_faces.empty() || m.normals.size() == m.vertices.size());
    const bool uvs = !m.uvs.empty() && (!m.uv_faces.empty() || m.uvs.size() == m.vertices.size());
    for (const std::size_t f : chosen) {
        for (int k = 0; k < 3; ++k) {
            arrays.positions.push_back(m.vertices[m.faces[f][k]]);
            if (normals) arrays.normals.push_back(m.normals[nf[f][k]]);
            if (uvs) arrays.uvs.push_back(m.uvs[uf[f][k]]);
        }
        const auto base = std::uint32_t(arrays.positions.size() - 3);
        arrays.triangles.push_back({base, base + 1, base + 2});
    }
    return arrays;
}

}  // namespace

void PovItemReader::mesh2(const PovToken& keyword, PovObject& object) {
    Mesh2 m;
    const std::size_t limit =
        std::min<std::size_t>(parser_.options().max_array_elements, kMaxMeshElements);
    // `name { count, item, item, ... }`: the count, then each item read by `item`.
    const auto block = [&](const PovToken& name, auto&& item) {
        parser_.expect("{", "after " + name.text);
        const PovToken at = parser_.peek();
        const double count = parser_.finite_float("as the number of " + name.text);
        if (!(count >= 0 && count <= double(limit) && count == std::floor(count)))
            throw parser_.error_at(at, name.text +
                                           " must count a whole number of items from 0 "
                                           "to " +
                                           std::to_string(limit));
        for (std::size_t i = 0; i < std::size_t(count); ++i) {
            parser_.accept(",");
            item();
        }
        parser_.accept(",");
        const PovToken close = parser_.next();
        if (!close.is_symbol("}"))
            throw parser_.error_at(close, name.text + " holds more items than its count, " +
                                              std::to_string(std::size_t(count)));
    };
    const auto indices = [&](std::vector<std::array<std::uint32_t, 3>>& into,
                             std::string_view what) {
        const PovToken at = parser_.peek();
        const PovVector v = point(what);
        std::array<std::uint32_t, 3> face{};
        for (int k = 0; k < 3; ++k) {
            if (!(v[k] >= 0 && v[k] < double(limit) && v[k] == std::floor(v[k])))
                throw parser_.error_at(at, "a mesh2 index must be a whole number from 0");
            face[k] = std::uint32_t(v[k]);
        }
        into.push_back(face);
    };
    for (;;) {
        const PovToken& ahead = parser_.peek_item();
        if (ahead.is_word("vertex_vectors")) {
            const PovToken name = parser_.next();
            block(name, [&] { m.vertices.push_back(to_point(point("as a vertex"))); });
        } else if (ahead.is_word("normal_vectors")) {
            const PovToken name = parser_.next();
            block(name, [&] { m.normals.push_back(Normal3(to_vector(point("as a normal")))); });
        } else if (ahead.is_word("uv_vectors")) {
            const PovToken name = parser_.next();
            block(name, [&] {
                const PovVector uv = parser_.finite_vector("as a uv", 2);
                m.uvs.push_back({float(uv[0]), float(uv[1])});
            });
        } else if (ahead.is_word("texture_list")) {
            const PovToken name = parser_.next();
            block(name, [&] {
                const PovToken t = parser_.next();
                if (!t.is_word("texture"))
                    throw parser_.error_at(
                        t, "expected a texture in texture_list, got " + describe(t));
                m.textures.push_back(
                    std::make_shared<const PovTexture>(texture(*default_texture_)));
            });
        } else if (ahead.is_word("face_indices")) {
            const PovToken name = parser_.next();
            block(name, [&] {
                indices(m.faces, "as a face's vertex indices");
                // The face's textures after it: one index, or one a corner (POV-Ray blends
                // those; the face takes its first).
                m.face_texture.push_back(-1);
                for (int k = 0; k < 3; ++k) {
                    if (!parser_.accept(",")) break;
                    const PovToken& next = parser_.peek_item();
                    if (next.is_symbol("<") || next.is_symbol("}")) break;
                    const PovToken at = parser_.peek();
                    const double t = parser_.finite_float("as a face's texture index");
                    if (!(t >= 0 && t < double(m.textures.size()) && t == std::floor(t)))
                        throw parser_.error_at(at,
                                               "a face's texture index must be one of "
                                               "texture_list's, 0 to " +
                                                   std::to_string(m.textures.size()) +
                                                   " (excluded)");
                    if (k == 0) m.face_texture.back() = std::int64_t(t);
                    if (k == 1)
                        read_past("mesh2's textures at each corner of a face",
                                  "the face takes its first corner's");
                }
            });
        } else if (ahead.is_word("normal_indices")) {
            const PovToken name = parser_.next();
            block(name, [&] { indices(m.normal_faces, "as a face's normal indices"); });
        } else if (ahead.is_word("uv_indices")) {
            const PovToken name = parser_.next();
            block(name, [&] { indices(m.uv_faces, "as a face's uv indices"); });
        } else if (ahead.is_word("inside_vector")) {
            parser_.next();
            point("after inside_vector");
        } else {
            break;
        }
    }
    const auto check = [&](const Faces& faces, std::size_t size, std::string_view what) {
        if (!faces.empty() && faces.size() != m.faces.size())
            throw parser_.error_at(keyword, "mesh2 has " + std::to_string(m.faces.size()) +
                                                " faces and " + std::to_string(faces.size()) + " " +
                                                std::string(what));
        for (const auto& f : faces)
            for (const std::uint32_t i : f)
                if (i >= size)
                    throw parser_.error_at(keyword, "mesh2 " + std::string(what) + " index " +
                                                        std::to_string(i) + " is beyond its " +
                                                        std::to_string(size) + " items");
    };
    check(m.faces, m.vertices.size(), "face_indices");
    check(m.normal_faces, m.normals.size(), "normal_indices");
    check(m.uv_faces, m.uvs.size(), "uv_indices");
    // The faces by their texture: each texture's a mesh of its own, a union of them.
    std::map<std::int64_t, std::vector<std::size_t>> by_texture;
    for (std::size_t f = 0; f < m.faces.size(); ++f) by_texture[m.face_texture[f]].push_back(f);
    if (by_texture.empty()) by_texture[-1] = {};
    const auto mesh_of = [&](const std::vector<std::size_t>& chosen) -> Shape {
        MeshBuild built = build_mesh(arrays_of(m, chosen));
        if (!built.mesh) throw parser_.error_at(keyword, "mesh2: " + built.error);
        return TriangleMesh{built.mesh};
    };
    if (by_texture.size() == 1 && by_texture.begin()->first < 0) {
        object.shape = mesh_of(by_texture.begin()->second);
        return;
    }
    object.csg = PovObject::Csg::group;
    for (const auto& [texture, chosen] : by_texture) {
        PovObject part;
        part.shape = mesh_of(chosen);
        if (texture >= 0) part.texture = m.textures[std::size_t(texture)];
        part.fallback = default_texture_;
        part.at = keyword.at;
        object.children.push_back(std::make_shared<const PovObject>(std::move(part)));
    }
}

}  // namespace glint
