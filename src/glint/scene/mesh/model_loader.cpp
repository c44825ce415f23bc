// load_model: checks the file, runs the format's validator, imports with Assimp, flattens the
// node tree into world-space parts per material, and maps materials, lights and cameras.
#include "glint/scene/mesh/model_loader.h"

#include <assimp/BaseImporter.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <exception>
#include <map>
#include <set>
#include <span>
#include <system_error>
#include <utility>

#include "glint/geometry/vertex_normals.h"
#include "glint/image/image_error.h"
#include "glint/image/srgb.h"
#include "glint/image/texture_file.h"
#include "glint/math/constants.h"
#include "glint/scene/mesh/assimp_warnings.h"
#include "glint/scene/mesh/glb_validator.h"
#include "glint/scene/mesh/gltf_validator.h"
#include "glint/scene/mesh/material_mapping.h"
#include "glint/scene/mesh/mesh_limits.h"
#include "glint/scene/mesh/obj_validator.h"
#include "glint/scene/mesh/ply_validator.h"
#include "glint/scene/mesh/sandboxed_io_system.h"
#include "glint/scene/mesh/stl_validator.h"
#include "glint/scene/mesh/text_lines.h"
#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene_error.h"

namespace glint {

namespace {

enum class Format { obj, ply, gltf, stl };

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

Format format_of(const std::filesystem::path& file) {
    const std::string ext = lower(file.extension().string());
    if (ext == ".obj") return Format::obj;
    if (ext == ".ply") return Format::ply;
    if (ext == ".gltf" || ext == ".glb") return Format::gltf;
    if (ext == ".stl") return Format::stl;
    throw SceneError({file.string(), 0, 0},
                     "unknown mesh format \"" + file.extension().string() + "\"",
                     {"mesh formats are: .glb, .gltf, .obj, .ply, .stl"});
}

// Size and kind of the file, before anything is read.
void check_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (ec || !std::filesystem::exists(status)) {
        throw SceneError({file.string(), 0, 0}, "mesh file not found");
    }
    if (!std::filesystem::is_regular_file(status)) {
        throw SceneError({file.string(), 0, 0}, "not a regular file");
    }
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) throw SceneError({file.string(), 0, 0}, "cannot read file: " + ec.message());
    if (size == 0) throw SceneError({file.string(), 0, 0}, "file is empty");
    if (size > max_bytes) {
        throw SceneError({file.string(), 0, 0},
                         "file is " + std::to_string(size) + " bytes, more than the limit of " +
                             describe_file_limit(max_bytes),
                         {kRaiseFileLimitNote});
    }
}

using Matrix = aiMatrix4x4;

Point3 transform_point(const Matrix& m, aiVector3D p) {
    const aiVector3D q = m * p;
    return {q.x, q.y, q.z};
}

Vector3 transform_vector(const Matrix& m, aiVector3D v) {
    const aiVector3D q = aiMatrix3x3(m) * v;
    return {q.x, q.y, q.z};
}

// Parts are keyed by material and vertex layout, so that merged meshes have uniform arrays.
struct PartKey {
    unsigned material;
    bool normals;
    bool uvs;
    auto operator<=>(const PartKey&) const = default;
};

class Importer {
public:
    Importer(std::filesystem::path file, const ModelOptions& options)
        : file_(std::move(file)),
          name_(file_.string()),
          options_(options),
          sandbox_(options.sandbox ? *options.sandbox : make_read_sandbox(file_)) {}

    Model run() {
        const Format format = format_of(file_);
        check_file(file_, mesh_limit());
        validate(format);
        const aiScene* scene = import(format);
        if (!scene->mRootNode) throw error("the file has no scene");
        collect(*scene);
        if (arrays_.empty()) {
            throw error("the file has no triangles (" + std::to_string(scene->mNumMeshes) +
                        " meshes, none with faces of 3 or more vertices)");
        }
        build_parts(*scene, format);
        map_lights(*scene);
        map_cameras(*scene);
        return std::move(model_);
    }

private:
    std::uintmax_t mesh_limit() const { return sandbox_.file_limit(kMaxMeshFileBytes); }

    SceneError error(std::string message, std::vector<std::string> notes = {}) const {
        return SceneError({name_, 0, 0}, std::move(message), std::move(notes));
    }

    void validate(Format format) {
        if (format == Format::obj) {
            const std::string text = read_text_file(name_, mesh_limit());
            ObjCheck check = validate_obj(file_, text, sandbox_);
            model_.warnings = std::move(check.warnings);
            material_libraries_ = std::move(check.material_libraries);
            undefined_materials_ = std::move(check.undefined_materials);
        } else if (format == Format::ply) {
            const std::string bytes = read_text_file(name_, mesh_limit());
            validate_ply(file_, bytes);
        } else if (format == Format::stl) {
            const std::string bytes = read_text_file(name_, mesh_limit());
            validate_stl(file_, bytes);
        } else if (format == Format::gltf) {
            const std::string bytes = read_text_file(name_, mesh_limit());
            const bool binary = lower(file_.extension().string()) == ".glb";
            if (binary) validate_glb(file_, bytes);
            validate_gltf_json(file_, bytes, binary);
        }
    }

    // glTF accessors are not validated before Assimp reads them (that needs a JSON parser);
    // Assimp drops the faces whose indices are out of range with only a log message, which is
    // caught here and made an error, whether or not any faces are left.
    void check_assimp_log(Format format, const AssimpWarnings& log) const {
        if (format == Format::gltf && log.any_contains("out-of-range indices")) {
            throw error(
                "an index is out of range: a primitive's indices refer to vertices beyond "
                "the count of its POSITION accessor",
                {"Assimp drops the triangles that use such indices; glint refuses the "
                 "file rather than render it with holes"});
        }
    }

    // Every position, normal and texture coordinate finite.
    void check_finite(const aiScene& scene) const {
        const auto finite = [](const aiVector3D& v) {
            return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        };
        for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
            const aiMesh& mesh = *scene.mMeshes[m];
            const std::string mesh_name = mesh.mName.length > 0
                                              ? "mesh \"" + std::string(mesh.mName.C_Str()) + "\""
                                              : "mesh " + std::to_string(m);
            const auto refuse = [&](const char* what, unsigned v, const aiVector3D& value) {
                throw error(mesh_name + ": " + what + " " + std::to_string(v) +
                            " has a coordinate that is not finite (" + std::to_string(value.x) +
                            ", " + std::to_string(value.y) + ", " + std::to_string(value.z) + ")");
            };
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                if (!finite(mesh.mVertices[v])) refuse("vertex", v, mesh.mVertices[v]);
                if (mesh.mNormals && !finite(mesh.mNormals[v]))
                    refuse("normal", v, mesh.mNormals[v]);
                for (unsigned c = 0; c < AI_MAX_NUMBER_OF_TEXTURECOORDS; ++c) {
                    if (mesh.mTextureCoords[c] && !finite(mesh.mTextureCoords[c][v]))
                        refuse("texture coordinate", v, mesh.mTextureCoords[c][v]);
                }
            }
        }
    }

    // Assimp offers a file that the importers of its extension do not recognise to every other
    // importer it has, parsers glint's checks know nothing of (its OpenGEX importer took 19
    // bytes of text named .gltf and overflowed a buffer). glTF files, which glint checks least,
    // must be recognised by a glTF importer. (Assimp reads OBJ, PLY and STL files with their own
    // importers whatever those say of them.)
    bool recognised_by_gltf_importer() const {
        const std::string extension = lower(file_.extension().string()).substr(1);
        for (std::size_t i = 0; i < importer_.GetImporterCount(); ++i) {
            Assimp::BaseImporter* candidate = importer_.GetImporter(i);
            std::set<std::string> extensions;
            candidate->GetExtensionList(extensions);
            if (extensions.contains(extension) &&
                candidate->CanRead(name_, importer_.GetIOHandler(), false)) {
                return true;
            }
        }
        return false;
    }

    const aiScene* import(Format format) {
        unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                         aiProcess_SortByPType | aiProcess_ValidateDataStructure;
        // Points and lines are not surfaces; SortByPType drops them.
        importer_.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                     aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        if (options_.crease_angle_degrees) {
            // The file's normals would keep vertices apart that glint's smoothing joins.
            flags |= aiProcess_RemoveComponent;
            importer_.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
        }
        // The importer owns its IOSystem, which also closes the files an import leaves open.
        auto* io = new SandboxedIOSystem(sandbox_, file_);
        importer_.SetIOHandler(io);
        const aiScene* scene = nullptr;
        const AssimpWarnings log;
        if (format == Format::gltf && !recognised_by_gltf_importer()) {
            throw error(
                "Assimp's glTF importers do not recognise it (it is neither glTF JSON "
                "nor a GLB container they can parse)");
        }
        try {
            // Numbers are checked before post-processing: joining vertices compares positions,
            // and a NaN one would be merged away with its triangle instead of being reported.
            scene = importer_.ReadFile(name_, aiProcess_ValidateDataStructure);
        } catch (const std::exception& e) {
            throw error(std::string("Assimp cannot read it: ") + e.what());
        }
        // Assimp reports a refused file as one it could not open (or, asking whether it exists,
        // not at all): the sandbox says why, whatever Assimp made of it.
        if (io->refused()) {
            auto refusal = check_read(sandbox_, *io->refused(), "referenced file", *io->refused());
            refusal->notes.insert(
                refusal->notes.begin() + 1,
                "Assimp opens it for the model (a glTF buffer, an OBJ material library)");
            throw error(refusal->message, refusal->notes);
        }
        if (scene) {
            check_finite(*scene);
            try {
                scene = importer_.ApplyPostProcessing(flags);
            } catch (const std::exception& e) {
                throw error(std::string("Assimp cannot read it: ") + e.what());
            }
        }
        check_assimp_log(format, log);
        if (!scene)
            throw error(std::string("Assimp cannot read it: ") + importer_.GetErrorString());
        return scene;
    }

    // Walks the node tree (without recursion: a file may nest nodes deeply), appending every
    // mesh a node uses, in world space, to the arrays of its part.
    void collect(const aiScene& scene) {
        std::vector<std::pair<const aiNode*, Matrix>> stack{{scene.mRootNode, Matrix()}};
        while (!stack.empty()) {
            const auto [node, parent] = stack.back();
            stack.pop_back();
            const Matrix world = parent * node->mTransformation;
            node_transforms_.emplace(node->mName.C_Str(), world);
            const float det = world.Determinant();
            if (node->mNumMeshes > 0 && (det == 0 || !std::isfinite(det))) {
                // A zero scale flattens the meshes to nothing and has no normal transform.
                model_.warnings.push_back(name_ + ": node \"" + node->mName.C_Str() +
                                          "\" has a singular transform; its meshes are skipped");
                continue;
            }
            for (unsigned i = 0; i < node->mNumMeshes; ++i) {
                const unsigned index = node->mMeshes[i];
                if (index >= scene.mNumMeshes) throw error("a node refers to a missing mesh");
                append(*scene.mMeshes[index], world);
            }
            for (unsigned i = node->mNumChildren; i-- > 0;) {
                stack.emplace_back(node->mChildren[i], world);
            }
        }
    }

    void append(const aiMesh& mesh, const Matrix& world) {
        if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || mesh.mNumFaces == 0) return;
        const bool normals = mesh.HasNormals() && !options_.crease_angle_degrees;
        const bool uvs = mesh.HasTextureCoords(0);
        MeshData& out = arrays_[{mesh.mMaterialIndex, normals, uvs}];
        if (out.positions.size() + mesh.mNumVertices > kMaxMeshElements ||
            out.triangles.size() + mesh.mNumFaces > kMaxMeshElements) {
            throw error("the model has more than 2^29 - 1 vertices or triangles");
        }
        const std::string mesh_name =
            mesh.mName.length > 0 ? "mesh \"" + std::string(mesh.mName.C_Str()) + "\"" : "a mesh";
        const auto offset = std::uint32_t(out.positions.size());
        // A mirroring transform turns the winding, and so the geometric normal, inside out.
        const bool flip = world.Determinant() < 0;
        const Matrix normal_matrix = Matrix(world).Inverse().Transpose();
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            out.positions.push_back(transform_point(world, mesh.mVertices[v]));
            if (normals) {
                const Vector3 n = transform_vector(normal_matrix, mesh.mNormals[v]);
                out.normals.push_back(Normal3(n));  // build_mesh normalises
            }
            if (uvs) out.uvs.push_back({mesh.mTextureCoords[0][v].x, mesh.mTextureCoords[0][v].y});
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;  // triangulated; anything else was a point or line
            std::array<std::uint32_t, 3> t{};
            for (int k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) {
                    throw error(mesh_name + ": face " + std::to_string(f) + " uses vertex " +
                                std::to_string(face.mIndices[k]) + " but the mesh has " +
                                std::to_string(mesh.mNumVertices) + " vertices");
                }
                t[std::size_t(k)] = offset + face.mIndices[k];
            }
            if (flip) std::swap(t[1], t[2]);
            out.triangles.push_back(t);
        }
    }

    void build_parts(const aiScene& scene, Format format) {
        std::map<unsigned, std::uint32_t> material_index;
        std::size_t dropped = 0;
        for (auto& [key, arrays] : arrays_) {
            if (arrays.triangles.empty()) continue;
            if (options_.crease_angle_degrees) {
                compute_vertex_normals(arrays,
                                       std::clamp(*options_.crease_angle_degrees, 0.f, 180.f));
            }
            MeshBuild built = build_mesh(std::move(arrays));
            if (!built.mesh) throw error(built.error);
            dropped += built.degenerate_dropped;
            auto [it, inserted] = material_index.try_emplace(key.material, 0);
            if (inserted) {
                it->second = std::uint32_t(model_.materials.size());
                model_.materials.push_back(material(scene, key.material, format));
            }
            model_.bounds = merge(model_.bounds, built.mesh->bounds);
            model_.parts.push_back({std::move(built.mesh), it->second});
        }
        if (dropped > 0) {
            model_.warnings.push_back(name_ + ": " + std::to_string(dropped) +
                                      " degenerate triangle" + (dropped == 1 ? "" : "s") +
                                      " dropped");
        }
    }

    Material material(const aiScene& scene, unsigned index, Format format) {
        if (index >= scene.mNumMaterials) return Material{"default"};
        const aiMaterial& m = *scene.mMaterials[index];
        aiString name;
        m.Get(AI_MATKEY_NAME, name);
        const std::string material_name = name.C_Str();
        // PLY and STL have no materials (Assimp makes one up); neither do OBJ faces without
        // usemtl, or with a usemtl name no MTL defines. They get glint's default material.
        if (format == Format::ply || format == Format::stl ||
            material_name == AI_DEFAULT_MATERIAL_NAME ||
            std::find(undefined_materials_.begin(), undefined_materials_.end(), material_name) !=
                undefined_materials_.end()) {
            return Material{material_name.empty() || format != Format::obj ? "default"
                                                                           : material_name};
        }
        const auto resolve = [&](const std::string& path, Color scale, TextureWrap wrap) {
            return ImageTexture{texture_image(scene, path, material_name), scale, wrap};
        };
        return map_material(
            m, format == Format::gltf ? MaterialConvention::gltf : MaterialConvention::obj,
            resolve);
    }

    std::shared_ptr<const MipMap> texture_image(const aiScene& scene, const std::string& path,
                                                const std::string& material_name) {
        const std::vector<std::string> notes{"the texture of material \"" + material_name + "\""};
        if (const aiTexture* embedded = scene.GetEmbeddedTexture(path.c_str())) {
            const std::string key = name_ + "[" + path + "]";
            if (auto it = textures_.find(key); it != textures_.end()) return it->second;
            try {
                auto image = std::make_shared<const MipMap>(decode_embedded(*embedded, key));
                return textures_[key] = image;
            } catch (const ImageError& e) {
                throw SceneError({name_, 0, 0}, "embedded texture " + path + ": " + e.detail,
                                 notes);
            }
        }
        // Relative to the MTL files first (OBJ), then to the model file; only those inside the
        // sandbox are looked at.
        std::vector<std::filesystem::path> candidates;
        for (const auto& library : material_libraries_) {
            candidates.push_back(library.parent_path() / path);
        }
        candidates.push_back(file_.parent_path() / path);
        std::error_code ec;
        const auto found = std::find_if(candidates.begin(), candidates.end(), [&](const auto& c) {
            return may_read(sandbox_, c) && std::filesystem::is_regular_file(c, ec);
        });
        if (found == candidates.end()) {
            for (const auto& candidate : candidates) {
                if (auto refusal = check_read(sandbox_, candidate, "texture file", path)) {
                    refusal->notes.push_back(notes[0]);
                    throw error(refusal->message, refusal->notes);
                }
            }
            throw SceneError({name_, 0, 0}, "texture file \"" + path + "\" not found",
                             {"looked for " + candidates.back().string(), notes[0]});
        }
        const std::string key = found->lexically_normal().string();
        if (auto it = textures_.find(key); it != textures_.end()) return it->second;
        try {
            record_read(sandbox_, *found);
            return textures_[key] = std::make_shared<const MipMap>(
                       load_texture_image(*found, sandbox_.file_limit(kMaxTextureFileBytes),
                                          sandbox_.limits.image_pixels));
        } catch (const ImageError& e) {
            throw SceneError({found->string(), 0, 0}, e.detail, notes);
        }
    }

    static Image decode_embedded(const aiTexture& texture, const std::string& name) {
        if (texture.mHeight == 0) {  // compressed (PNG, JPEG): mWidth is its size in bytes
            return decode_texture_image(
                std::span(reinterpret_cast<const unsigned char*>(texture.pcData), texture.mWidth),
                name);
        }
        Image image(int(texture.mWidth), int(texture.mHeight));
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            const aiTexel& t = texture.pcData[i];
            image.pixels[i] = {srgb_to_linear(t.r / 255.0f), srgb_to_linear(t.g / 255.0f),
                               srgb_to_linear(t.b / 255.0f)};
        }
        return image;
    }

    const Matrix* node_transform(const aiString& name) const {
        const auto it = node_transforms_.find(name.C_Str());
        return it == node_transforms_.end() ? nullptr : &it->second;
    }

    void map_lights(const aiScene& scene) {
        for (unsigned i = 0; i < scene.mNumLights; ++i) {
            const aiLight& light = *scene.mLights[i];
            const std::string label = "light \"" + std::string(light.mName.C_Str()) + "\"";
            const Matrix* world = node_transform(light.mName);
            const Matrix m = world ? *world : Matrix();
            const Color color =
                Color{light.mColorDiffuse.r, light.mColorDiffuse.g, light.mColorDiffuse.b} *
                kGltfLightUnitsToGlint;
            if (!is_finite(color)) {
                model_.warnings.push_back(name_ + ": " + label +
                                          " has a non-finite colour; skipped");
                continue;
            }
            switch (light.mType) {
                case aiLightSource_SPOT:
                    model_.warnings.push_back(name_ + ": spot " + label +
                                              " imported as a point light (glint has no spot "
                                              "lights)");
                    [[fallthrough]];
                case aiLightSource_POINT:
                    // glTF point lights fall off with 1/d^2 and nothing else.
                    model_.lights.push_back(
                        PointLight{transform_point(m, light.mPosition), color, {0, 0, 1}});
                    break;
                case aiLightSource_DIRECTIONAL: {
                    const Vector3 d = transform_vector(m, light.mDirection);
                    if (!(length(d) > 0) || !is_finite(d)) {
                        model_.warnings.push_back(name_ + ": " + label +
                                                  " has no direction; skipped");
                        break;
                    }
                    model_.lights.push_back(DirectionalLight{normalize(d), color});
                    break;
                }
                default:
                    model_.warnings.push_back(name_ + ": " + label +
                                              " is of a kind glint does not import; skipped");
            }
        }
    }

    void map_cameras(const aiScene& scene) {
        for (unsigned i = 0; i < scene.mNumCameras; ++i) {
            const aiCamera& camera = *scene.mCameras[i];
            const std::string label = "camera \"" + std::string(camera.mName.C_Str()) + "\"";
            const Matrix* world = node_transform(camera.mName);
            const Matrix m = world ? *world : Matrix();
            // glTF cameras sit at their node's origin and look down its -z axis. Assimp 5.2 also
            // copies the node's translation into mPosition, so mPosition is not added again.
            ModelCamera out{{}, camera.mName.C_Str()};
            out.spec.from = transform_point(m, aiVector3D(0, 0, 0));
            out.spec.at = out.spec.from + transform_vector(m, camera.mLookAt);
            out.spec.up = transform_vector(m, camera.mUp);
            if (camera.mOrthographicWidth > 0) {
                // Assimp gives xmag and xmag / ymag; the view's height is 2 ymag.
                out.spec.projection = Projection::orthographic;
                const float aspect = camera.mAspect > 0 ? camera.mAspect : 1;
                out.spec.height = 2 * camera.mOrthographicWidth / aspect;
            } else {
                // Assimp 5.2's glTF importer stores yfov * aspectRatio as the horizontal fov.
                const float aspect = camera.mAspect > 0 ? camera.mAspect : 1;
                out.spec.fov = degrees(camera.mHorizontalFOV / aspect);
            }
            const Vector3 view = out.spec.at - out.spec.from;
            const bool ok = is_finite(out.spec.from) && is_finite(view) && length(view) > 0 &&
                            length(cross(view, out.spec.up)) > 0 &&
                            (out.spec.projection == Projection::orthographic
                                 ? out.spec.height > 0 && std::isfinite(out.spec.height)
                                 : out.spec.fov > 0 && out.spec.fov < 180);
            if (!ok) {
                model_.warnings.push_back(name_ + ": " + label + " is degenerate; skipped");
                continue;
            }
            model_.cameras.push_back(std::move(out));
        }
    }

    std::filesystem::path file_;
    std::string name_;
    ModelOptions options_;
    ReadSandbox sandbox_;
    Assimp::Importer importer_;
    Model model_;
    std::map<PartKey, MeshData> arrays_;
    std::map<std::string, Matrix> node_transforms_;  // world from node, by node name
    std::map<std::string, std::shared_ptr<const MipMap>> textures_;
    std::vector<std::filesystem::path> material_libraries_;
    std::vector<std::string> undefined_materials_;
};

}  // namespace

Model load_model(const std::filesystem::path& file, const ModelOptions& options) {
    try {
        return Importer(file, options).run();
    } catch (const SceneError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw SceneError({file.string(), 0, 0}, "out of memory while importing the model");
    } catch (const std::exception& e) {
        throw SceneError({file.string(), 0, 0},
                         std::string("cannot import the model: ") + e.what());
    }
}

}  // namespace glint
