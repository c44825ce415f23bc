// The YAML scene loader: reads the file within its size limit, parses it with yaml-cpp, and walks
// the sections in a fixed order (materials before the objects that name them). Whatever goes
// wrong, including inside yaml-cpp, leaves as a SceneError.
#include "glint/scene/yaml/yaml_scene_loader.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <sstream>

#include "glint/scene/animation.h"
#include "glint/scene/yaml/yaml_fog.h"
#include "glint/scene/yaml/yaml_lights.h"
#include "glint/scene/yaml/yaml_map_reader.h"
#include "glint/scene/yaml/yaml_materials.h"
#include "glint/scene/yaml/yaml_medium.h"
#include "glint/scene/yaml/yaml_settings.h"
#include "glint/scene/yaml/yaml_shape_reader.h"
#include "glint/scene/yaml/yaml_sky.h"

namespace glint {

namespace {

// An optional section given with no value (`lights:`) counts as absent.
const MapEntry* section(const MapReader& scene, std::string_view key) {
    const MapEntry* entry = scene.find(key);
    return entry && !entry->value.IsNull() ? entry : nullptr;
}

std::string indexed(std::string_view key, std::size_t i) {
    return std::string(key) + "[" + std::to_string(i) + "]";
}

// An object: one SceneObject, or one per part of a mesh file. A mesh without a `material` key
// keeps its file's materials. emits_light on an object whose materials emit nothing is warned
// about: it does nothing.
void read_object(ShapeReader& shapes, const YAML::Node& node, const Field& field,
                 MaterialTable& materials, std::size_t index, Scene& scene) {
    LargeVector<SceneObject>& out = scene.objects;
    ShapeReader::ObjectResult r =
        shapes.read_object(node, field, {"material", "casts_shadow", "emits_light"});
    const MapEntry* material = r.map.find("material");
    const bool casts_shadow = r.map.boolean("casts_shadow", true);
    const bool emits_light = r.map.boolean("emits_light", true);
    std::vector<std::uint32_t> file_materials;
    if (r.model && !material) {
        for (const Material& m : r.model->materials)
            file_materials.push_back(materials.add(m, text_position(node.Mark())));
    }
    const std::uint32_t shared = file_materials.empty() ? materials.resolve(material, index) : 0;
    for (std::size_t i = 0; i < r.shapes.size(); ++i) {
        const std::uint32_t m =
            file_materials.empty() ? shared : file_materials[r.model->parts[i].material];
        out.push_back({std::move(r.shapes[i]), m, casts_shadow, emits_light});
    }
    if (const MapEntry* key = r.map.find("emits_light")) {
        const auto emits = [&](std::uint32_t m) { return !is_black(scene.materials[m].emission); };
        const bool any = file_materials.empty()
                             ? emits(shared)
                             : std::any_of(file_materials.begin(), file_materials.end(), emits);
        if (!any)
            scene.warnings.push_back(shapes.source().warning_at(
                key->key_node,
                "emits_light does nothing: the object's material has no emission "
                "(give the material an emission for it to light the scene)"));
    }
}

// An area light's face: it glows in the light's colour, and neither casts shadows nor lights the
// scene (the light does).
void add_light_face(LightEntry& entry, std::size_t index, TextPosition where,
                    MaterialTable& materials, Scene& scene) {
    Material glow;
    glow.name = "(light " + std::to_string(index) + ")";
    glow.ka = glow.kd = glow.ks = 0;
    glow.emission = std::get<AreaLight>(entry.light).color;
    scene.objects.push_back({std::move(*entry.visible_shape), materials.add(std::move(glow), where),
                             /*casts_shadow=*/false, /*emits_light=*/false});
    scene.sources.objects.push_back(where);
}

Scene read_scene(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& root) {
    const MapReader scene(source, root, Field("", "scene"), "scene",
                          {"image", "camera", "animation", "ambient", "sky", "fog", "atmosphere",
                           "materials", "lights", "define", "objects"});
    Scene result;
    if (const MapEntry* image = section(scene, "image")) {
        result.settings = read_image(source, image->value, scene.field("image"), sandbox.limits);
        if (const YAML::Node photons = image->value["photons"])
            result.sources.photons = text_position(photons.Mark());
        if (const YAML::Node next_event = image->value["next_event"])
            result.sources.next_event = text_position(next_event.Mark());
    }
    std::vector<std::string> warnings;
    result.camera =
        read_camera(source, scene.require("camera").value, scene.field("camera"), warnings);
    if (const MapEntry* animation = section(scene, "animation"))
        result.animation = read_animation(source, animation->value, scene.field("animation"));
    result.ambient = scene.color("ambient", result.ambient);
    if (const MapEntry* sky = section(scene, "sky")) {
        const MapEntry* image = scene.find("image");
        if (image && image->value.IsMap()) {
            if (const YAML::Node background = image->value["background"]) {
                throw source.error_at(sky->key_node,
                                      "a scene has a sky or a background colour, not both",
                                      {"image.background is given at line " +
                                           std::to_string(background.Mark().line + 1),
                                       "the sky is what rays that leave the scene see"});
            }
        }
        result.sky = read_sky(source, sandbox, sky->value, scene.field("sky"));
    }
    if (const MapEntry* fog = section(scene, "fog"))
        result.fogs = read_fogs(source, fog->value, scene.field("fog"));
    if (const MapEntry* atmosphere = section(scene, "atmosphere"))
        result.atmosphere = read_atmosphere(source, atmosphere->value, scene.field("atmosphere"));

    result.sources.file = source.file_name();
    MaterialTable materials(source, sandbox, result.materials, result.sources.materials);
    if (const MapEntry* named = section(scene, "materials")) {
        materials.read_named(named->value, scene.field("materials"));
    }
    if (const MapEntry* lights = section(scene, "lights")) {
        const auto items =
            read_sequence(source, lights->value, scene.field("lights"), "a list of lights");
        for (std::size_t i = 0; i < items.size(); ++i) {
            LightEntry entry = read_light(source, items[i], {"", indexed("lights", i)});
            const TextPosition where = text_position(items[i].Mark());
            if (entry.visible_shape) add_light_face(entry, i, where, materials, result);
            if (entry.motion)
                result.moving_lights.push_back(
                    {std::uint32_t(result.lights.size()), entry.light, entry.motion});
            result.lights.push_back(std::move(entry.light));
            result.sources.lights.push_back(where);
        }
    }
    ShapeReader shapes(source, sandbox, materials);
    if (const MapEntry* define = section(scene, "define")) {
        shapes.read_definitions(define->value, scene.field("define"));
    }
    if (const MapEntry* objects = section(scene, "objects")) {
        const auto items =
            read_sequence(source, objects->value, scene.field("objects"), "a list of objects");
        for (std::size_t i = 0; i < items.size(); ++i) {
            read_object(shapes, items[i], {"", indexed("objects", i)}, materials, i, result);
            // A mesh file's parts all at their object.
            result.sources.objects.resize(result.objects.size(), text_position(items[i].Mark()));
        }
    }
    // The loader's warnings in the order of the file's sections: camera, objects, then what the
    // model files said.
    warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
    warnings.insert(warnings.end(), shapes.warnings().begin(), shapes.warnings().end());
    result.warnings = std::move(warnings);
    place_lights(result, result.camera.shutter_open);
    return result;
}

// Records where each document starts, and nothing else.
class DocumentStarts : public YAML::EventHandler {
public:
    std::vector<YAML::Mark> starts;

    void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
};

// A scene is one document. YAML::LoadAll() cannot count them: on some invalid input (a "," where
// a document should start) yaml-cpp 0.7 reports an empty document without consuming the token,
// and LoadAll() loops until memory runs out (jbeder/yaml-cpp#1040). So the documents are
// counted here, at most two, and a document that starts where the previous one did is that
// stuck token.
void check_single_document(const YamlSource& source, const std::string& text) {
    std::istringstream stream(text);
    YAML::Parser parser(stream);
    DocumentStarts documents;
    for (int i = 0; i < 2 && parser.HandleNextDocument(documents); ++i) {
    }
    if (documents.starts.size() < 2) return;
    const YAML::Mark& second = documents.starts[1];
    if (second.pos == documents.starts[0].pos) {
        const std::string_view line = source.line(second.line);
        const auto column = std::size_t(std::max(0, second.column));
        const std::string token = column < line.size() ? std::string(1, line[column]) : "";
        throw source.error_at(second, 1, "invalid YAML: unexpected " + quote(token));
    }
    throw source.error_at(second, 1, "a scene file holds one YAML document; this is a second one");
}

// Whether the text may hold more than the root document that YAML::Load() returned, which
// ignores the rest. yaml-cpp ends a flow collection or an indented root where it closes and takes
// what follows as another document; but a block map at the left margin runs to the end of the
// text unless a line starts with a document marker ("---", "..."). Counting the documents costs
// a second parse, as long as the first, so the usual scene skips it.
bool may_hold_more_documents(const YamlSource& source, const YAML::Node& root) {
    const YAML::Mark mark = root.Mark();
    if (!root.IsMap() || mark.is_null() || mark.column != 0) return true;
    const std::string_view first = source.line(mark.line);
    if (first.starts_with('{') || first.starts_with('[')) return true;
    for (int i = mark.line + 1; i < source.line_count(); ++i) {
        const std::string_view line = source.line(i);
        if (line.starts_with("---") || line.starts_with("...")) return true;
    }
    return false;
}

Scene parse_documents(const YamlSource& source, const ReadSandbox& sandbox, std::string_view text) {
    const std::string yaml(text);
    const YAML::Node root = YAML::Load(yaml);
    if (may_hold_more_documents(source, root)) check_single_document(source, yaml);
    if (root.IsNull()) {
        throw source.error("the scene is empty; it needs at least a camera",
                           {"see docs/scene-format.md for an example"});
    }
    if (!root.IsMap()) {
        throw source.error_at(root,
                              "the top level of a scene must be a map of sections "
                              "(image, camera, materials, lights, objects), got " +
                                  describe(root));
    }
    return read_scene(source, sandbox, root);
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

Scene parse_yaml_scene(std::string_view text, const std::string& file_name,
                       const ReadSandbox& sandbox) {
    const YamlSource source(text, file_name);
    try {
        return parse_documents(source, sandbox, text);
    } catch (...) {
        rethrow_as_scene_error(source, "the scene");
    }
}

Scene parse_yaml_scene(std::string_view text, const std::string& file_name) {
    return parse_yaml_scene(text, file_name, make_read_sandbox(file_name));
}

Scene load_yaml_scene(const std::filesystem::path& file) {
    return load_yaml_scene(file, make_read_sandbox(file));
}

Scene load_yaml_scene(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    const std::string name = file.string();
    const auto fail = [&](const std::string& why) {
        return SceneError({name, 0, 0}, "cannot read scene file: " + why);
    };
    const std::uintmax_t limit = sandbox.file_limit(kMaxSceneFileBytes);
    const auto too_large = [&] {
        return SceneError({name, 0, 0},
                          "scene file is larger than the limit of " + describe_file_limit(limit),
                          {kRaiseFileLimitNote});
    };
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (ec) throw fail(ec.message());
    if (std::filesystem::is_directory(status)) throw fail("it is a directory");
    // Regular files are measured first; pipes and devices are caught by the bounded read below.
    if (std::filesystem::is_regular_file(status)) {
        const auto size = std::filesystem::file_size(file, ec);
        if (ec) throw fail(ec.message());
        if (size > limit) throw too_large();
    }
    const std::unique_ptr<std::FILE, FileCloser> f(std::fopen(name.c_str(), "rb"));
    if (!f) throw fail(std::strerror(errno));
    std::string text;
    char buffer[1 << 16];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, f.get())) {
        text.append(buffer, n);
        if (text.size() > limit) throw too_large();
    }
    if (std::ferror(f.get())) throw fail(std::strerror(errno));
    return parse_yaml_scene(text, name, sandbox);
}

}  // namespace glint
