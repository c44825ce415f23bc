// Reads POV-Ray's objects, textures (pigment, finish), interiors and transforms from the token
// stream, as the items of a scene or the values of #declare.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "glint/geometry/spline_outlines.h"
#include "glint/image/png_io.h"
#include "glint/scene/pov/pov_items.h"
#include "glint/scene/pov/pov_parser.h"

namespace glint {

// The note under an error that names what glint does not read yet.
inline constexpr const char* kSeeCompatibility = "docs/povray.md lists what glint reads";

class PovItemReader {
public:
    // Warnings go to `warnings` ("layered textures: only each object's bottom layer is used").
    PovItemReader(PovParser& parser, std::vector<std::string>& warnings);

    // The item that `keyword` starts, or nothing when it starts none.
    std::optional<PovItem> read(const PovToken& keyword);
    static bool starts_object(const std::string& keyword);
    // What #default set: the texture of objects that give none.
    const std::shared_ptr<const PovTexture>& default_texture() const { return default_texture_; }

    PovObject object(const PovToken& keyword);
    PovTexture texture(const PovTexture& base);
    // `layer`, with its own layers, laid over `below`, as POV-Ray lays every texture written
    // after another; at most kMaxTextureLayers in all.
    static constexpr std::size_t kMaxTextureLayers = 64;
    PovTexture laid_over(PovTexture below, PovTexture layer, const PovToken& at);
    // texture { checker texture { } texture { } }: the keyword read; onto a checker pigment.
    void checker_texture(const PovToken& keyword, PovTexture& t);
    PovPigment pigment(const PovPigment& base);
    // What a pigment holds, over `base`, up to `closing` ("}", or "]" in a pigment_map).
    PovPigment pigment_body(const PovPigment& base, std::string_view closing);
    // pigment_map { [value pigment-body] ... }: a colour map whose stops hold pigments.
    PovColorMap pigment_map(const PovToken& keyword);
    // A map's braces and [value ...] entries, each read past its value by `entry`; sorted.
    PovColorMap blend_map(const PovToken& keyword, std::string_view entry_kind,
                          const std::function<void(double, PovColorMap&)>& entry);
    // normal { [declared] pattern [amount] modifiers } over `base` (pov_normal_reader.cpp).
    PovNormal normal(const std::optional<PovNormal>& base);
    PovColorMap color_map(const PovToken& keyword);
    PovFinish finish(const PovFinish& base);
    PovInterior interior(const PovInterior& base);
    // media { }, its keyword read (pov_media_reader.cpp).
    PovMedium media(const PovToken& keyword);
    // density { }, its keyword read: a pigment whose colour is the density.
    PovPigment density();
    // material { [declared] texture interior transforms }, over what the object has.
    PovMaterial material(const PovMaterial& base);
    PovCamera camera(const PovToken& keyword);
    PovLight light_source(const PovToken& keyword);
    PovSkySphere sky_sphere(const PovToken& keyword);
    PovFog fog(const PovToken& keyword);
    // translate, rotate, scale, matrix or transform, whose keyword has been read; nothing for
    // another word.
    std::optional<Transform> transform_step(const PovToken& keyword);
    // The float after a keyword that may take one (`metallic 0.5`, `hollow off`), else 1.
    double optional_amount();
    // Whether a float is next (a number, an expression, a declared float, on or off), and
    // that float, taken, when one is.
    bool number_next();
    std::optional<double> amount_if_given();
    // The bounding box of an object as POV-Ray's min_extent and max_extent give it: huge where
    // it is unbounded, empty where it has no surface.
    Bounds3 extent(const PovObject& object);

private:
    Shape shape(const PovToken& keyword);
    Shape mesh(const PovToken& keyword);
    // mesh2 { arrays, faces }: its mesh, or a union of a mesh for each of its textures
    // (pov_mesh2_reader.cpp).
    void mesh2(const PovToken& keyword, PovObject& object);
    Shape height_field(const PovToken& keyword);  // pov_height_field_reader.cpp
    // pov_extrusion_reader.cpp: prism, lathe and sor, and text as a union of a prism a letter.
    Shape prism(const PovToken& keyword);
    Shape lathe(const PovToken& keyword);
    Shape sor(const PovToken& keyword);
    Shape lathe_of(const PovToken& keyword, std::variant<Outline, std::string> curve);
    // linear_spline ... bezier_spline, taken when it is next.
    std::optional<SplineKind> spline_keyword();
    // `count, <x, y>, ...`, at least `least` points.
    std::vector<Point2> point_list(const std::string& shape, int least);
    // `open` and `sturm` after a shape's points: whether it is open.
    bool open_and_sturm();
    Shape julia_fractal(const PovToken& keyword);
    Shape superellipsoid(const PovToken& keyword);  // pov_superellipsoid_reader.cpp
    Shape blob(const PovToken& keyword);            // pov_blob_reader.cpp
    Shape isosurface(const PovToken& keyword);      // pov_isosurface_reader.cpp
    // function [(parameters)] { body }, the keyword read (pov_function_reader.cpp).
    PovFunction function(const PovToken& keyword);
    // The glint expression text of a function body up to its closing brace, its parameters
    // written $0, $1, ...; what glint cannot compute yet noted in `unsupported`.
    std::string function_body(const std::vector<std::string>& parameters, std::string& unsupported);
    void text(const PovToken& keyword, PovObject& object);
    // sphere_sweep as a merge of its chain of spheres and cones (pov_sphere_sweep_reader.cpp).
    void sphere_sweep(const PovToken& keyword, PovObject& object);
    // The corners of triangles as read, three a triangle, with a smooth one's normals.
    struct MeshCorners {
        std::vector<Point3> positions;
        std::vector<std::optional<Normal3>> normals;
    };
    void triangle(const PovToken& keyword, MeshCorners& corners);
    // The arrays of a mesh: normals at every corner when any triangle is smooth.
    static MeshData mesh_arrays(const MeshCorners& corners);
    void csg(const PovToken& keyword, PovObject& object);
    // The objects of a clipped_by or bounded_by block, added to `so_far`: an intersection in the
    // object's own space. Nothing for `clipped_by { bounded_by }` and `bounded_by { clipped_by }`,
    // which name the other block (`*names_other` is then set).
    std::shared_ptr<const PovObject> object_list(const PovToken& keyword, const PovObject& object,
                                                 std::shared_ptr<const PovObject> so_far,
                                                 bool* names_other);
    // A polynomial surface's region: the box of its bounded_by (or clipped_by) objects, when it
    // has them.
    void set_polynomial_region(const PovToken& keyword, PovObject& object);
    // The modifiers after an object's own values, to the closing brace.
    void modifiers(PovObject& object);
    template <typename Item>
    std::optional<Item> declared(const PovToken& name);
    // The declared item next in the stream, taken: a name (`Stone`) or an element of an array of
    // such items (`Stones[I]`, its subscripts read); nothing, and nothing taken, otherwise.
    template <typename Item>
    std::optional<Item> take_declared();
    PovVector point(std::string_view what) { return parser_.finite_vector(what, 3); }
    float number(std::string_view what) { return float(parser_.finite_float(what)); }
    SceneError unsupported(const PovToken& token, std::string_view where);
    // image_map { ... }, its keyword read: an image pigment (pov_image_map_reader.cpp).
    PovPigment image_map(const PovToken& keyword);
    // `[type] "file"` in an image_map or height_field: the image, found and read through the
    // sandbox, in linear light; with `palette`, a palette PNG's indices too.
    Image image_file(const PovToken& keyword, std::optional<PaletteImage>* palette = nullptr);
    // Whether `name` is a pattern glint reads in a pigment (gradient, marble, ...).
    static bool is_pigment_pattern(std::string_view name);
    // gradient x, checker C1 C2, marble, ...: the pattern `name` starts, before its modifiers.
    PovPigment pattern(const PovToken& name);
    // A pigment modifier of a pattern (color_map, turbulence, waves, ...); false for another word.
    bool pattern_modifier(const PovToken& token, PovPigment& p);
    // warp { turbulence ... } after `warp`, onto the pattern's turbulence; false, the warp read
    // past, for a warp glint does not read (another kind, or a second turbulence).
    bool warp(const PovToken& keyword, PovPigment& p);
    void read_default(const PovToken& directive);
    // A warning, once a scene for each `what`, that it is read and left out, and what glint
    // does instead.
    void read_past(const std::string& what, const std::string& instead);

    PovParser& parser_;
    std::vector<std::string>& warnings_;
    std::shared_ptr<const PovTexture> default_texture_ = std::make_shared<const PovTexture>();
    bool warned_fog_noise_ = false;
    bool warned_checker_finish_ = false;
    bool warned_crackle_ = false;
    std::set<std::string> read_past_;
};

template <typename Item>
std::optional<Item> PovItemReader::declared(const PovToken& name) {
    if (name.kind != PovTokenKind::identifier) return std::nullopt;
    PovValue* value = parser_.symbols().find(name.text);
    if (!value) return std::nullopt;
    const auto* ref = std::get_if<std::shared_ptr<const PovItemRef>>(value);
    if (!ref) return std::nullopt;
    if (const Item* item = std::get_if<Item>(&(*ref)->item)) return *item;
    return std::nullopt;
}

template <typename Item>
std::optional<Item> PovItemReader::take_declared() {
    const PovToken& next = parser_.peek_item();
    if (auto item = declared<Item>(next)) {
        parser_.next();
        return item;
    }
    if (next.kind != PovTokenKind::identifier) return std::nullopt;
    PovValue* value = parser_.symbols().find(next.text);
    const auto* array = value ? std::get_if<std::shared_ptr<PovArray>>(value) : nullptr;
    // An array of items of this kind: one of its elements holds one.
    const auto holds_item = [](const std::shared_ptr<PovValue>& e) {
        const auto* ref = e ? std::get_if<std::shared_ptr<const PovItemRef>>(e.get()) : nullptr;
        return ref && std::holds_alternative<Item>((*ref)->item);
    };
    if (!array || std::none_of((*array)->elements.begin(), (*array)->elements.end(), holds_item))
        return std::nullopt;
    const PovToken name = parser_.next();
    const auto element = parser_.array_element(name, **array);
    const auto* ref = std::get_if<std::shared_ptr<const PovItemRef>>(&element);
    if (const Item* item = ref ? std::get_if<Item>(&(*ref)->item) : nullptr) return *item;
    throw parser_.error_at(name, "this element of " + name.text +
                                     " holds another kind of value than its other elements");
}

// The box of a shape as POV-Ray's extents see it in its own space: a plane along an axis its
// half-space, a quadric not bounded yet its inside's (inside_extent), an implicit surface not
// bounded yet everywhere.
Bounds3 own_extent(const Shape& shape);

// A quadric that nothing bounds along an axis is cut this far out along it: POV-Ray's infinite
// cylinders and the like, far beyond any scene.
inline constexpr float kFarQuadric = 1e5f;
// The region with its unbounded sides cut at kFarQuadric.
Bounds3 far_bounded(Bounds3 region);

// The region grown by 1e-4 of its size along each axis: where it comes from the surface's own
// extent or an intersection's, the surface touches its sides, and a region cut exactly there loses
// hits to rounding.
Bounds3 loosened(Bounds3 region);

// A polynomial surface (quadric or implicit) searched within `region`, finite and not empty.
void bound_polynomial(Shape& shape, const Bounds3& region);

Point3 to_point(const PovVector& v);
Vector3 to_vector(const PovVector& v);

}  // namespace glint
