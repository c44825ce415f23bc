// Reading materials and their textures (checker, image), and resolving objects' material
// references.
#include "glint/scene/yaml/yaml_materials.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <memory>

#include "glint/image/image_error.h"
#include "glint/image/texture_file.h"
#include "glint/scene/suggest.h"
#include "glint/scene/yaml/yaml_file_path.h"
#include "glint/scene/yaml/yaml_medium.h"
#include "glint/shading/noise.h"

namespace glint {

namespace {
constexpr std::string_view kTextureTypes[] = {"checker", "fbm",        "granite", "image",
                                              "marble",  "turbulence", "wood"};
constexpr std::string_view kNoiseTypes[] = {"fbm", "granite", "marble", "turbulence", "wood"};
constexpr NoisePattern kNoisePatterns[] = {NoisePattern::fbm, NoisePattern::granite,
                                           NoisePattern::marble, NoisePattern::turbulence,
                                           NoisePattern::wood};
constexpr std::string_view kWraps[] = {"clamp", "repeat"};
constexpr std::string_view kFilters[] = {"trilinear", "ewa", "bilinear", "nearest"};
constexpr std::string_view kCheckerSpaces[] = {"solid", "uv"};
constexpr std::string_view kHighlights[] = {"blinn", "phong"};
constexpr std::string_view kEmissionSides[] = {"both", "front"};

// Glasses by name: Sellmeier coefficients B1..B3, C1..C3 (um^2) from the makers' data sheets.
struct NamedGlass {
    std::string_view name;
    std::array<float, 6> sellmeier;
};
constexpr NamedGlass kGlasses[] = {
    {"fused-silica", {0.6961663f, 0.4079426f, 0.8974794f, 0.004679148f, 0.01351206f, 97.934f}},
    {"n-bk7", {1.03961212f, 0.231792344f, 1.01046945f, 0.00600069867f, 0.0200179144f, 103.560653f}},
    {"n-sf11", {1.73759695f, 0.313747346f, 1.89878101f, 0.013188707f, 0.0623068142f, 155.23629f}},
};
constexpr std::string_view kGlassNames[] = {"fused-silica", "n-bk7", "n-sf11"};
constexpr std::string_view kDispersionForms[] = {"abbe", "cauchy", "sellmeier"};
// Notes list the defined materials only while the list stays readable.
constexpr std::size_t kMaxListedNames = 30;
}  // namespace

namespace {

// An image file, relative to the scene file and inside the sandbox, decoded to linear RGB.
Texture read_image_texture(const YamlSource& source, const ReadSandbox& sandbox,
                           const MapReader& map) {
    ImageTexture texture;
    const MapEntry& file = map.require("file");
    const std::string name = read_string(source, file.value, map.field("file"));
    const auto path = scene_file_path(source, sandbox, file.value, name, "texture");
    try {
        record_read(sandbox, path);
        texture.image = std::make_shared<const MipMap>(load_texture_image(
            path, sandbox.file_limit(kMaxTextureFileBytes), sandbox.limits.image_pixels));
    } catch (const ImageError& e) {
        throw source.error_at(file.value, "cannot read texture " + quote(name) + ": " + e.detail,
                              {"looked for " + path.string()});
    }
    texture.scale = map.color("scale", texture.scale);
    texture.wrap = map.choice("wrap", kWraps, "wrap mode", "wrap modes", "repeat") == "clamp"
                       ? TextureWrap::clamp
                       : TextureWrap::repeat;
    const std::string filter = map.choice("filter", kFilters, "filter", "filters", "trilinear");
    texture.filter = filter == "ewa"        ? TextureFilter::ewa
                     : filter == "bilinear" ? TextureFilter::bilinear
                     : filter == "nearest"  ? TextureFilter::nearest
                                            : TextureFilter::trilinear;
    return texture;
}

Texture read_checker_texture(const MapReader& map) {
    CheckerTexture checker;
    checker.even = map.color("even", checker.even);
    checker.odd = map.color("odd", checker.odd);
    checker.size = map.number("size");
    const std::string space =
        map.choice("space", kCheckerSpaces, "checker space", "checker spaces", "solid");
    checker.space = space == "uv" ? CheckerSpace::uv : CheckerSpace::solid;
    return checker;
}

// The keys every noise pattern takes, after the type.
NoiseSpec read_noise_spec(const MapReader& map, std::string_view type) {
    NoiseSpec spec;
    const auto* it = std::find(std::begin(kNoiseTypes), std::end(kNoiseTypes), type);
    spec.pattern = kNoisePatterns[it - std::begin(kNoiseTypes)];
    spec.scale = map.number("scale");
    // Wood's rings wander less than marble's veins by default, as in Ebert et al.
    spec.turbulence = map.number_or("turbulence", spec.pattern == NoisePattern::wood ? 0.2f : 1.0f);
    spec.octaves = map.integer("octaves");
    return spec;
}

// Default ramps: white marble with grey veins, light and dark wood, grey granite, black to white.
std::vector<Color> default_colors(NoisePattern pattern) {
    switch (pattern) {
        case NoisePattern::marble:
            return {{0.92f, 0.9f, 0.86f}, {0.92f, 0.9f, 0.86f}, {0.35f, 0.35f, 0.4f}};
        case NoisePattern::wood:
            return {{0.75f, 0.52f, 0.3f}, {0.45f, 0.27f, 0.12f}};
        case NoisePattern::granite:
            return {{0.75f, 0.72f, 0.7f}, {0.2f, 0.2f, 0.22f}, {0.05f, 0.05f, 0.05f}};
        default:
            return {{0, 0, 0}, {1, 1, 1}};
    }
}

Texture read_noise_texture(const YamlSource& source, const MapReader& map, std::string_view type) {
    NoiseTexture texture{read_noise_spec(map, type), {}};
    if (const MapEntry* colors = map.find("colors")) {
        const auto stops =
            read_sequence(source, colors->value, map.field("colors"), "a list of colours");
        if (stops.size() < 2) {
            throw source.error_at(colors->value, "a colour ramp needs at least 2 colours, got " +
                                                     std::to_string(stops.size()));
        }
        for (const YAML::Node& stop : stops)
            texture.colors.push_back(read_color(source, stop, map.field("colors")));
    } else {
        texture.colors = default_colors(texture.spec.pattern);
    }
    return texture;
}

// A number, or a noise pattern that varies it between low and high ({type, low, high, ...}).
std::optional<NoiseScalar> read_scalar_map(const MapReader& material, std::string_view key,
                                           float& constant) {
    const MapEntry* entry = material.find(key);
    if (!entry || !entry->value.IsMap()) {
        constant = material.number_or(key, constant);
        return std::nullopt;
    }
    // low and high within the material key's range.
    const Range range = entity_schema(EntityFamily::material, "material").key(key).range;
    const YamlSource& source = material.source();
    auto entries = read_map(source, entry->value, material.field(key));
    const std::string type = read_type(source, entry->value, entries, "pattern", kNoiseTypes);
    const MapReader map(source, entry->value, std::move(entries), type + " " + std::string(key),
                        entity_schema(EntityFamily::pattern, "value"));
    NoiseScalar s{read_noise_spec(map, type)};
    s.low = map.number("low", range, 0.0f);
    s.high = map.number("high", range, 1.0f);
    return s;
}

std::optional<BumpMap> read_bump(const MapReader& material) {
    const MapEntry* entry = material.find("bump");
    if (!entry) return std::nullopt;
    const YamlSource& source = material.source();
    auto entries = read_map(source, entry->value, material.field("bump"));
    const std::string type = read_type(source, entry->value, entries, "pattern", kNoiseTypes);
    const MapReader map(source, entry->value, std::move(entries), type + " bump",
                        entity_schema(EntityFamily::pattern, "bump"));
    BumpMap bump{read_noise_spec(map, type)};
    bump.strength = map.number("strength");
    return bump;
}

}  // namespace

Texture read_texture(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                     const Field& field) {
    auto entries = read_map(source, node, field);
    const std::string type = read_type(source, node, entries, "texture", kTextureTypes);
    if (std::find(std::begin(kNoiseTypes), std::end(kNoiseTypes), type) != std::end(kNoiseTypes)) {
        const MapReader map(source, node, std::move(entries), type + " texture",
                            entity_schema(EntityFamily::texture, type));
        return read_noise_texture(source, map, type);
    }
    if (type == "image") {
        const MapReader map(source, node, std::move(entries), "image texture",
                            entity_schema(EntityFamily::texture, "image"));
        return read_image_texture(source, sandbox, map);
    }
    const MapReader map(source, node, std::move(entries), "checker texture",
                        entity_schema(EntityFamily::texture, "checker"));
    return read_checker_texture(map);
}

namespace {

// `dispersion`: a glass's name, {abbe: V} around the material's ior (n_d), {cauchy: [A, B]} or
// {sellmeier: [B1, B2, B3, C1, C2, C3]}. The formulas fix the index themselves, so the material
// takes no `ior` with them; its ior becomes their value at the d line.
void read_dispersion(const MapReader& map, Material& m) {
    const YamlSource& source = map.source();
    const MapEntry* entry = map.find("dispersion");
    if (!entry) return;
    const YAML::Node& node = entry->value;
    const Field field = map.field("dispersion");
    Dispersion d;
    bool from_ior = false;  // the Abbe form disperses around the material's ior
    if (node.IsScalar()) {
        const std::string name = read_string(source, node, field);
        const auto glass = std::find_if(std::begin(kGlasses), std::end(kGlasses),
                                        [&](const NamedGlass& g) { return g.name == name; });
        if (glass == std::end(kGlasses))
            throw unknown_name(source, node, "glass", "glasses", name, kGlassNames);
        d = {DispersionModel::sellmeier, glass->sellmeier};
    } else {
        auto entries = read_map(source, node, field);
        if (entries.size() != 1) {
            throw source.error_at(
                node, "dispersion is a map with one key, got " + std::to_string(entries.size()),
                {"forms are: " + join(kDispersionForms) + ", or a glass name"});
        }
        const MapEntry& form = entries.front();
        const Field form_field{"dispersion", form.key, form.key_node};
        if (form.key == "abbe") {
            const float abbe = read_number(source, form.value, form_field, kPositive);
            if (!(m.ior > 1)) {
                throw source.error_at(form.key_node,
                                      "an Abbe number needs the material's ior (n_d) above 1, "
                                      "got " +
                                          format_number(m.ior));
            }
            d = cauchy_from_abbe(m.ior, abbe);
            from_ior = true;
        } else if (form.key == "cauchy" || form.key == "sellmeier") {
            const bool cauchy = form.key == "cauchy";
            const auto c =
                read_sequence(source, form.value, form_field,
                              cauchy ? "[A, B]" : "[B1, B2, B3, C1, C2, C3]", cauchy ? 2 : 6);
            d.model = cauchy ? DispersionModel::cauchy : DispersionModel::sellmeier;
            for (std::size_t i = 0; i < c.size(); ++i)
                d.c[i] = read_number(source, c[i], form_field);
        } else {
            throw unknown_name(source, form.key_node, "dispersion form", "forms", form.key,
                               kDispersionForms);
        }
    }
    if (const std::string problem = describe_problem(d, m.ior); !problem.empty())
        throw source.error_at(node, "dispersion " + problem);
    if (!from_ior && map.has("ior")) {
        throw source.error_at(map.require("ior").key_node,
                              "a material whose dispersion gives its index takes no \"ior\"",
                              {"its ior is the formula's value at the d line, 587.56 nm"});
    }
    m.dispersion = d;
    m.ior = refractive_index(d, m.ior, kReferenceWavelength);
}

}  // namespace

Material read_material(const YamlSource& source, const ReadSandbox& sandbox, const YAML::Node& node,
                       const Field& field, std::string what, std::string name) {
    const MapReader map(source, node, field, std::move(what),
                        entity_schema(EntityFamily::material, "material"));
    Material m;
    m.name = std::move(name);
    if (const MapEntry* color = map.find("color")) {
        m.color = color->value.IsMap()
                      ? read_texture(source, sandbox, color->value, map.field("color"))
                      : Texture(read_color(source, color->value, map.field("color")));
    }
    m.ka = map.number_or("ka", m.ka);
    m.kd = map.number_or("kd", m.kd);
    m.ks = map.number_or("ks", m.ks);
    m.shininess = map.number_or("shininess", m.shininess);
    m.brilliance = map.number_or("brilliance", m.brilliance);
    m.metallic = map.number_or("metallic", m.metallic);
    const std::string highlight =
        map.choice("highlight", kHighlights, "highlight", "highlights", "blinn");
    m.highlight = highlight == "phong" ? Highlight::phong : Highlight::blinn;
    MaterialMaps maps;
    maps.reflect = read_scalar_map(map, "reflect", m.reflect);
    const bool fresnel_reflection = map.boolean("reflect_fresnel", false);
    if (map.has("reflect_facing") || fresnel_reflection) {
        // Fresnel's reflectance from 0 unless told, as POV-Ray's.
        AngularReflection a;
        a.facing = map.number_or("reflect_facing", fresnel_reflection ? 0.0f : m.reflect);
        a.falloff = map.number_or("reflect_falloff", a.falloff);
        a.fresnel = fresnel_reflection;
        m.reflect_angular = a;
    } else if (map.has("reflect_falloff")) {
        throw source.error_at(map.require("reflect_falloff").key_node,
                              "reflect_falloff needs reflect_facing: kr runs from it to reflect");
    }
    m.reflect_metallic = map.number_or("reflect_metallic", m.reflect_metallic);
    m.reflect_color = map.color("reflect_color", m.reflect_color);
    for (const float c : {m.reflect_color.r, m.reflect_color.g, m.reflect_color.b})
        if (!(c <= 1))
            throw source.error_at(map.require("reflect_color").value,
                                  "reflect_color's channels must be in [0, 1]");
    m.transmit = map.number_or("transmit", m.transmit);
    m.tint = map.number_or("tint", m.tint);
    m.fade.distance = map.number_or("fade_distance", m.fade.distance);
    m.fade.power = map.number_or("fade_power", m.fade.power);
    m.fade.color = map.color("fade_color", m.fade.color);
    // The keys' ranges hold the distance and power; the colour's channels are checked here.
    if (const std::string problem = describe_problem(m.fade); !problem.empty())
        throw source.error_at(map.has("fade_color") ? map.require("fade_color").value : node,
                              problem);
    if (std::optional<Medium> medium = read_medium(map, "medium_"))
        m.media.push_back(std::move(*medium));
    m.hollow = map.boolean("hollow", m.hollow);
    m.ior = map.number_or("ior", m.ior);
    m.fresnel = map.boolean("fresnel", m.fresnel);
    read_dispersion(map, m);
    maps.roughness = read_scalar_map(map, "roughness", m.roughness);
    // transmit_roughness defaults to roughness, map and all.
    m.transmit_roughness = m.roughness;
    maps.transmit_roughness = map.has("transmit_roughness")
                                  ? read_scalar_map(map, "transmit_roughness", m.transmit_roughness)
                                  : maps.roughness;
    maps.bump = read_bump(map);
    if (maps.reflect || maps.roughness || maps.transmit_roughness || maps.bump)
        m.maps = std::make_shared<const MaterialMaps>(std::move(maps));
    m.emission = map.color("emission", m.emission);
    m.emits_both_sides = map.choice("emission_sides", kEmissionSides, "emission side",
                                    "emission sides", "both") == "both";
    return m;
}

void MaterialTable::read_named(const YAML::Node& section, const Field& field) {
    for (const MapEntry& entry : read_map(source_, section, field)) {
        if (entry.key.empty()) throw source_.error_at(entry.key_node, "material name is empty");
        Material material =
            read_material(source_, sandbox_, entry.value, {"", entry.key, entry.key_node},
                          "material " + quote(entry.key), entry.key);
        named_.emplace(entry.key, add(std::move(material), text_position(entry.key_node.Mark())));
    }
}

std::uint32_t MaterialTable::resolve(const MapEntry* entry, std::size_t object_index) {
    if (!entry) {
        // A material the file names "default" replaces the built-in one for every object that
        // gives none.
        if (const auto it = named_.find(kDefaultName); it != named_.end()) return it->second;
        if (!default_) {
            Material material;
            material.name = kDefaultName;
            default_ = add(std::move(material), {});  // built in: read nowhere
        }
        return *default_;
    }
    return resolve_given(*entry, "(object " + std::to_string(object_index) + ")");
}

std::uint32_t MaterialTable::resolve_given(const MapEntry& entry, const std::string& inline_name) {
    const YAML::Node& value = entry.value;
    const Field field{"", "material", entry.key_node};
    if (value.IsMap()) {
        return add(read_material(source_, sandbox_, value, field, "material", inline_name),
                   text_position(value.Mark()));
    }
    if (!value.IsScalar()) throw type_error(source_, value, field, "a material name or map");
    const std::string& name = value.Scalar();
    if (const auto it = named_.find(name); it != named_.end()) return it->second;

    std::vector<std::string_view> names;
    for (const auto& [defined, index] : named_) names.push_back(defined);  // sorted: a std::map
    std::string note;
    if (names.empty()) {
        note = "no materials are defined; define them in the top-level \"materials\" map";
    } else if (names.size() <= kMaxListedNames) {
        note = "materials are: " + join(names) + did_you_mean(name, names);
    } else {
        note = std::to_string(names.size()) + " materials are defined" + did_you_mean(name, names);
    }
    throw source_.error_at(value, "unknown material " + quote(name), {note});
}

std::uint32_t MaterialTable::add(Material material, TextPosition where) {
    // An index must fit the object's 32-bit field; a file this size is refused long before.
    if (materials_.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw source_.error("too many materials");
    }
    materials_.push_back(std::move(material));
    positions_.push_back(where);
    return std::uint32_t(materials_.size() - 1);
}

}  // namespace glint
