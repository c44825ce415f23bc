// Recording the ray tree: the integrators' values as they are, and beside them the numbers a
// reader needs (N.L, H, the occluder, Snell's angles), worked out again from the same inputs.
#include "glint/render/explain/ray_tree_recorder.h"

#include <cmath>
#include <type_traits>

#include "glint/geometry/shape.h"
#include "glint/shading/optics.h"
#include "glint/shading/phong.h"

namespace glint {

RayTreeRecorder::RayTreeRecorder(const World& world, RayTree& tree)
    : world_(world), tree_(tree), feelers_(world) {}

void RayTreeRecorder::begin_ray(const Ray& ray, int depth, float weight) {
    RayNode node;
    node.ray = ray;
    node.depth = depth;
    node.weight = weight;
    const int index = int(tree_.nodes.size());
    if (!stack_.empty()) {
        RayNode& parent = current();
        BranchRecord& b = branch_of(next_.value_or(RayKind::reflected));
        b.child = index;
        node.kind = b.kind;
        node.parent = stack_.back();
        // What the child brings passes through its parent's fog too.
        const Color fog = parent.fog ? parent.fog->transmittance : Color{1, 1, 1};
        node.throughput = parent.throughput * fog * b.factor;
    }
    next_.reset();
    tree_.nodes.push_back(std::move(node));
    stack_.push_back(index);
}

void RayTreeRecorder::end_ray(Color value) {
    current().value = value;
    stack_.pop_back();
}

void RayTreeRecorder::missed(Color background) {
    current().stop = StopReason::missed;
    current().background = background;
}

void RayTreeRecorder::hit(const SurfaceContext& c, const Hit& hit) {
    RayNode& n = current();
    const Material& m = *c.material;
    n.t = hit.shape_hit.t;
    n.object = hit.primitive;
    const Shape& shape = world_.primitives()[hit.primitive].shape;
    n.shape = std::string(shape_name(shape));
    // A placed mesh passes its triangle's index up through its transforms.
    const Shape* inner = &shape;
    while (const auto* placed = std::get_if<Transformed>(inner)) inner = placed->shape.get();
    if (std::holds_alternative<TriangleMesh>(*inner)) n.triangle = hit.shape_hit.part;
    n.material = m.name;
    n.point = c.sp.p;
    n.geometric_normal = to_vector(c.ng);
    n.shading_normal = to_vector(c.n);
    n.entering = c.entering;
    n.pencil = c.pencil;
    n.emission = c.emission;
    n.ambient = ambient_term(m, c.ambient_color, world_.ambient());
}

void RayTreeRecorder::fog(const FogEffect& effect, bool inside) {
    current().fog = effect;
    current().fog_inside = inside;
}

void RayTreeRecorder::stop(StopReason reason) { current().stop = reason; }

std::string light_name(const World& world, std::size_t light, bool object_light) {
    if (object_light) {
        const std::uint32_t object = world.object_lights()[light].primitive;
        return "emitting object " + std::to_string(object) + " (" +
               std::string(shape_name(world.primitives()[object].shape)) + ")";
    }
    const std::string index = " " + std::to_string(light);
    return std::visit(
        [&](const auto& l) -> std::string {
            using L = std::decay_t<decltype(l)>;
            if constexpr (std::is_same_v<L, PointLight>) return "point light" + index;
            if constexpr (std::is_same_v<L, SpotLight>) return "spot light" + index;
            if constexpr (std::is_same_v<L, DirectionalLight>) return "directional light" + index;
            if constexpr (std::is_same_v<L, AreaLight>) {
                const char* shape = std::holds_alternative<Sphere>(l.shape) ? "sphere"
                                    : std::holds_alternative<Disk>(l.shape) ? "disk"
                                                                            : "rectangle";
                return "area light" + index + " (" + shape + ")";
            }
        },
        world.lights()[light]);
}

LightSampleRecord RayTreeRecorder::sample_record(std::size_t light, const SurfaceContext& c,
                                                 const LightSample& ls, float time, Color term) {
    const Material& m = *c.material;
    LightSampleRecord r;
    r.to_light = ls.to_light;
    r.distance = ls.distance;
    r.intensity = ls.intensity;
    r.n_dot_l = dot(c.n, ls.to_light);
    r.faces_light = r.n_dot_l > 0 && ls.intensity.r + ls.intensity.g + ls.intensity.b > 0;
    r.term = term;
    if (!r.faces_light) return r;
    RayStats unused;
    r.shadow = feelers_.transmittance(light, c.sp, c.ng, ls.to_light, ls.distance, time, unused);
    r.shadow_map = unused.shadow_map_lookups > 0;
    if (r.shadow != Color{1, 1, 1}) {
        const Ray feeler = world_.spawn_ray(c.sp.p, c.ng, ls.to_light, c.sp.error, time);
        const float reach = ls.distance - distance(c.sp.p, feeler.origin);
        if (const auto blocker = world_.intersect(feeler, {0, reach}, kVisibleToShadowRays))
            r.occluder = blocker->primitive;
    }
    r.blinn = m.highlight == Highlight::blinn;
    r.highlight_vector =
        r.blinn ? normalize(ls.to_light + c.to_viewer) : reflect(-ls.to_light, c.n);
    r.highlight_cosine =
        r.blinn ? dot(c.n, r.highlight_vector) : dot(r.highlight_vector, c.to_viewer);
    const float spec =
        m.ks > 0 ? m.ks * specular_factor(m.highlight, c.n, ls.to_light, c.to_viewer, m.shininess)
                 : 0;
    r.brilliance = m.brilliance;
    r.metallic = m.metallic;
    r.diffuse =
        r.shadow * ls.intensity * (m.kd * diffuse_factor(c.n, ls.to_light, m.brilliance) * c.color);
    r.highlight = r.shadow * ls.intensity * (spec * highlight_color(m, c.color));
    return r;
}

void RayTreeRecorder::light(std::size_t light, const SurfaceContext& c, const LightSample& ls,
                            float time, Color term) {
    LightRecord record;
    record.name = light_name(world_, light, false);
    record.light = light;
    record.samples.push_back(sample_record(light, c, ls, time, term));
    record.value = term;
    current().direct += term;
    current().lights.push_back(std::move(record));
}

void RayTreeRecorder::begin_light(std::size_t light, bool object_light) {
    LightRecord record;
    record.name = light_name(world_, light, object_light);
    record.light = light;
    record.object_light = object_light;
    record.averaged = true;
    current().lights.push_back(std::move(record));
}

void RayTreeRecorder::light_sample(const SurfaceContext& c, const LightSample& ls, Point2 u,
                                   float time, Color term) {
    LightRecord& record = current().lights.back();
    const std::size_t feeler_light = record.object_light ? ShadowFeelers::kNoLight : record.light;
    LightSampleRecord r = sample_record(feeler_light, c, ls, time, term);
    r.index = int(record.samples.size());
    r.u = u;
    record.samples.push_back(r);
}

void RayTreeRecorder::end_light(Color value) {
    current().lights.back().value = value;
    current().direct += value;
}

void RayTreeRecorder::wavelength(float u, float nanometres) {
    current().wavelength = nanometres;
    current().wavelength_u = u;
}

void RayTreeRecorder::branches(const SurfaceContext& c, const Branches& b, const MediumStack& media,
                               float wavelength, Vector3 incident, float weight) {
    RayNode& n = current();
    const float min_weight = world_.settings().min_weight;
    const auto cut = [&](float k) {
        return weight * k >= min_weight ? StopReason::none : StopReason::min_weight;
    };
    if (b.kr > 0)
        n.branches.push_back({RayKind::reflected, b.kr, b.kr * b.reflect_filter, {}, cut(b.kr)});
    if (c.material->transmit <= 0) return;
    const SnellIndices indices = snell_indices(c, media, wavelength);
    n.transmits = true;
    n.n1 = indices.n1;
    n.n2 = indices.n2;
    n.cos_incident = dot(-incident, to_vector(c.n));
    n.total_internal_reflection = b.kt == 0;  // branches_at moved kt to kr
    if (n.total_internal_reflection) {
        n.branches.push_back(
            {RayKind::refracted, 0, {}, {}, StopReason::total_internal_reflection});
        return;
    }
    n.cos_refracted = -dot(b.refracted, to_vector(c.n));
    n.branches.push_back({RayKind::refracted, b.kt, b.kt * b.filter, {}, cut(b.kt)});
}

BranchRecord& RayTreeRecorder::branch_of(RayKind kind) {
    for (BranchRecord& b : current().branches)
        if (b.kind == kind) return b;
    current().branches.push_back({kind, 0, {}, {}, StopReason::none});
    return current().branches.back();
}

void RayTreeRecorder::branch(RayKind kind, Color factor, std::optional<Point2> lobe_u) {
    BranchRecord& b = branch_of(kind);
    b.factor = factor;
    b.lobe_u = lobe_u;
    next_ = kind;
}

void RayTreeRecorder::delta_part(RayKind kind, float k, float survival, bool traced) {
    BranchRecord& b = branch_of(kind);
    b.k = k;
    b.survival = survival;
    if (!traced) b.stop = StopReason::roulette;
}

void RayTreeRecorder::blocked(RayKind kind, Point2 lobe_u) {
    BranchRecord& b = branch_of(kind);
    b.stop = StopReason::blocked_by_surface;
    b.lobe_u = lobe_u;
}

void RayTreeRecorder::path_vertex(const SurfaceContext&, const PathVertexRecord& record) {
    RayNode& n = current();
    n.path = record;
    // The terms evaluate() adds: the weighted emission, no ambient term, the sampled light.
    n.emission = record.le * record.emission_weight;
    n.ambient = {};
    for (const NextEventRecord& next : record.next_events) {
        LightRecord light;
        light.name = next.light;
        LightSampleRecord sample;
        sample.term = next.term;
        light.samples.push_back(sample);
        light.value = next.term;
        n.direct += next.term;
        n.lights.push_back(std::move(light));
    }
    if (record.photons >= 0) {
        LightRecord photons;
        photons.name = "photon map";
        LightSampleRecord sample;
        sample.term = record.photon_term;
        photons.samples.push_back(sample);
        photons.value = record.photon_term;
        n.direct += record.photon_term;
        n.lights.push_back(std::move(photons));
    }
}

}  // namespace glint
