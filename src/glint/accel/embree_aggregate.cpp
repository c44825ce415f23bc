// The Embree adapter: one process-wide device, a scene of triangle and user geometries built from
// glint's primitives, and the user-geometry callbacks that call glint's own intersection code.
#include "glint/accel/embree_aggregate.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace glint {

namespace {

const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
        case RTC_ERROR_UNKNOWN:
            break;
    }
    return "unknown error";
}

// Embree's live allocations on the device, as its memory monitor reports them.
std::atomic<std::int64_t> embree_live_bytes{0};

bool count_memory(void*, ssize_t bytes, bool) {
    embree_live_bytes += bytes;
    return true;  // never refuse an allocation
}

// Embree reports errors through a C callback, which must not throw: keep the first message of
// this thread until the build checks for it.
thread_local std::string first_error;

void record_error(void*, RTCError code, const char* message) {
    if (first_error.empty()) first_error = message && *message ? message : error_name(code);
}

// One device per process: creating one starts Embree's thread pool and picks its ISA kernels.
struct Device {
    RTCDevice handle = nullptr;
    std::string error;   // why there is no handle
    bool masks = false;  // whether this Embree build tests ray masks (EMBREE_RAY_MASK)

    Device() {
        handle = rtcNewDevice(nullptr);
        if (!handle) {
            error = std::string("Embree: cannot create a device: ") +
                    error_name(rtcGetDeviceError(nullptr));
            return;
        }
        rtcSetDeviceErrorFunction(handle, record_error, nullptr);
        rtcSetDeviceMemoryMonitorFunction(handle, count_memory, nullptr);
        masks = rtcGetDeviceProperty(handle, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED) != 0;
    }
    ~Device() {
        if (handle) rtcReleaseDevice(handle);
    }
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;
};

Device& device() {
    static Device device;
    return device;
}

// Builds and releases are serialised so that the memory monitor's count between the start and
// the end of a build is that scene's alone.
std::mutex& build_mutex() {
    static std::mutex mutex;
    return mutex;
}

// Throws the first error Embree reported on this thread since the last check, if any.
void check(const char* doing) {
    const RTCError code = rtcGetDeviceError(device().handle);
    if (code == RTC_ERROR_NONE && first_error.empty()) return;
    std::string message = first_error.empty() ? error_name(code) : first_error;
    first_error.clear();
    throw std::runtime_error(std::string("Embree: ") + doing + ": " + message);
}

}  // namespace

struct EmbreeAggregate::Scene {
    enum class Kind : std::uint8_t { mesh, triangles, user };
    struct Geometry {
        Kind kind = Kind::user;
        std::uint32_t visibility = 0;           // the ray mask bits that see it
        std::uint32_t primitive = 0;            // mesh: the primitive it is
        std::vector<std::uint32_t> primitives;  // triangles, user: Embree primID -> primitive
    };

    std::span<const Primitive> primitives;
    std::vector<Geometry> geometries;  // by Embree geomID
    std::vector<Bounds3> user_bounds;  // by primID of the user geometry
    // Embree reads vertices with 16-byte loads, so the last one needs 4 bytes of padding that a
    // std::vector<Point3> does not promise: vertices are copied, once per MeshData.
    std::vector<std::vector<float>> vertices;
    std::vector<std::vector<std::uint32_t>> indices;  // of loose triangles, 3 per triangle
    RTCScene handle = nullptr;
    std::size_t embree_bytes = 0;

    Scene() = default;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    ~Scene() {
        if (!handle) return;
        const std::lock_guard lock(build_mutex());
        rtcReleaseScene(handle);
    }

    std::uint32_t primitive_of(unsigned geom_id, unsigned prim_id) const {
        const Geometry& g = geometries[geom_id];
        return g.kind == Kind::mesh ? g.primitive : g.primitives[prim_id];
    }
};

namespace {

using Scene = EmbreeAggregate::Scene;

// Embree hands the context of a query back to the callbacks; it comes first, so a pointer to it
// is a pointer to the whole (the usual Embree idiom for per-query data).
struct QueryContext {
    RTCIntersectContext embree;
    const Scene* scene;
    // Per ray of the query (one, or a packet's, in the packet's order, which Embree keeps for
    // the callbacks): the glint hit of the last user primitive accepted, and the glint ray's time
    // and wavelength for user geometry (moving shapes): Embree's own time field stays 0, as its
    // static scene has no motion of its own.
    std::array<ShapeHit, kRayPacketSize> user_hit;
    std::array<float, kRayPacketSize> time{}, wavelength{};

    // Set up for a query over `s` (`coherent`: a packet of neighbouring rays).
    QueryContext(const Scene& s, bool coherent) : scene(&s) {
        rtcInitIntersectContext(&embree);
        if (coherent) embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    }
    // Ray i's time and wavelength, for the user geometry's callbacks.
    void carry(std::size_t i, const Ray& ray) {
        time[i] = ray.time;
        wavelength[i] = ray.wavelength;
    }
};

// Ray i of a callback's packet of N (one for rtcIntersect1), through Embree's SOA accessors.
Ray to_ray(RTCRayN* r, unsigned n, unsigned i, const QueryContext& context) {
    return {{RTCRayN_org_x(r, n, i), RTCRayN_org_y(r, n, i), RTCRayN_org_z(r, n, i)},
            {RTCRayN_dir_x(r, n, i), RTCRayN_dir_y(r, n, i), RTCRayN_dir_z(r, n, i)},
            context.time[i],
            context.wavelength[i]};
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
    const auto& scene = *static_cast<const Scene*>(args->geometryUserPtr);
    const Bounds3& b = scene.user_bounds[args->primID];
    RTCBounds& out = *args->bounds_o;
    out.lower_x = b.min.x;
    out.lower_y = b.min.y;
    out.lower_z = b.min.z;
    out.upper_x = b.max.x;
    out.upper_y = b.max.y;
    out.upper_z = b.max.z;
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
    auto& context = *reinterpret_cast<QueryContext*>(args->context);
    const Scene& scene = *context.scene;
    const std::uint32_t index = scene.geometries[args->geomID].primitives[args->primID];
    const Primitive& primitive = scene.primitives[index];
    const unsigned n = args->N;
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, n);
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] == 0 || (primitive.visibility & RTCRayN_mask(ray, n, i)) == 0) continue;
        float& t_far = RTCRayN_tfar(ray, n, i);
        const auto found = glint::intersect(primitive.shape, to_ray(ray, n, i, context),
                                            {RTCRayN_tnear(ray, n, i), t_far});
        if (!found) continue;
        // nearer()'s rule at equal t: the lower primitive index wins.
        const unsigned geom_id = RTCHitN_geomID(hit, n, i);
        if (found->t == t_far && geom_id != RTC_INVALID_GEOMETRY_ID &&
            scene.primitive_of(geom_id, RTCHitN_primID(hit, n, i)) < index)
            continue;
        t_far = found->t;
        // glint computes its own normal.
        RTCHitN_Ng_x(hit, n, i) = RTCHitN_Ng_y(hit, n, i) = RTCHitN_Ng_z(hit, n, i) = 0;
        RTCHitN_u(hit, n, i) = found->u;
        RTCHitN_v(hit, n, i) = found->v;
        RTCHitN_primID(hit, n, i) = args->primID;
        RTCHitN_geomID(hit, n, i) = args->geomID;
        RTCHitN_instID(hit, n, i, 0) = context.embree.instID[0];
        context.user_hit[i] = *found;
    }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto& context = *reinterpret_cast<const QueryContext*>(args->context);
    const Primitive& primitive =
        context.scene->primitives[context.scene->geometries[args->geomID].primitives[args->primID]];
    const unsigned n = args->N;
    for (unsigned i = 0; i < n; ++i) {
        if (args->valid[i] == 0 || (primitive.visibility & RTCRayN_mask(args->ray, n, i)) == 0)
            continue;
        float& t_far = RTCRayN_tfar(args->ray, n, i);
        if (glint::intersect(primitive.shape, to_ray(args->ray, n, i, context),
                             {RTCRayN_tnear(args->ray, n, i), t_far}))
            t_far = -kInfinity;  // Embree's mark of an occluded ray
    }
}

// For Embree builds without ray masks: reject triangle hits that the ray's mask does not see.
void mask_filter(const RTCFilterFunctionNArguments* args) {
    const auto visibility = *static_cast<const std::uint32_t*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i)
        if ((visibility & RTCRayN_mask(args->ray, args->N, i)) == 0) args->valid[i] = 0;
}

// Attaches an Embree triangle geometry over shared arrays (vertices padded, see Scene).
void attach_triangles(RTCScene scene, unsigned geom_id, const Scene::Geometry& g,
                      const float* vertices, std::size_t vertex_count,
                      const std::uint32_t* triangles, std::size_t triangle_count) {
    RTCGeometry geometry = rtcNewGeometry(device().handle, RTC_GEOMETRY_TYPE_TRIANGLE);
    check("creating a triangle geometry");
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0,
                               3 * sizeof(float), vertex_count);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, triangles, 0,
                               3 * sizeof(std::uint32_t), triangle_count);
    if (device().masks) {
        rtcSetGeometryMask(geometry, g.visibility);
    } else {
        rtcSetGeometryUserData(geometry, const_cast<std::uint32_t*>(&g.visibility));
        rtcSetGeometryIntersectFilterFunction(geometry, mask_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, mask_filter);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, geom_id);
    rtcReleaseGeometry(geometry);  // the scene holds it now
    check("adding triangles");
}

void attach_user(RTCScene scene, unsigned geom_id, const Scene& owner) {
    const Scene::Geometry& g = owner.geometries[geom_id];
    RTCGeometry geometry = rtcNewGeometry(device().handle, RTC_GEOMETRY_TYPE_USER);
    check("creating a user geometry");
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(g.primitives.size()));
    rtcSetGeometryUserData(geometry, const_cast<Scene*>(&owner));
    rtcSetGeometryBoundsFunction(geometry, user_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, user_intersect);
    rtcSetGeometryOccludedFunction(geometry, user_occluded);
    // The callbacks test each primitive's own visibility; the geometry mask is their union.
    if (device().masks) rtcSetGeometryMask(geometry, g.visibility);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, geom_id);
    rtcReleaseGeometry(geometry);
    check("adding user geometry");
}

std::vector<float> padded_copy(std::span<const Point3> points) {
    std::vector<float> out;
    out.reserve(3 * points.size() + 1);
    for (const Point3 p : points) out.insert(out.end(), {p.x, p.y, p.z});
    out.push_back(0);
    return out;
}

}  // namespace

EmbreeAggregate::EmbreeAggregate(std::span<const Primitive> primitives, EmbreeBuildQuality quality)
    : primitives_(primitives), scene_(std::make_unique<Scene>()) {
    if (!device().handle) throw std::runtime_error(device().error);
    if (primitives.size() > std::numeric_limits<std::uint32_t>::max())
        throw std::runtime_error("Embree: more than 2^32 primitives");
    Scene& s = *scene_;
    s.primitives = primitives;

    // Sort the primitives into geometries first: the callbacks keep pointers into them.
    std::map<std::uint32_t, std::vector<std::uint32_t>> loose_triangles;  // by visibility
    Scene::Geometry user{Scene::Kind::user};
    for (std::uint32_t i = 0; i < primitives.size(); ++i) {
        const Primitive& p = primitives[i];
        const Bounds3 b = glint::bounds(p.shape);
        if (!b.is_finite()) {
            unbounded_.push_back(i);
            continue;
        }
        bounds_ = merge(bounds_, b);
        if (std::holds_alternative<TriangleMesh>(p.shape)) {
            s.geometries.push_back({Scene::Kind::mesh, p.visibility, i, {}});
        } else if (std::holds_alternative<Triangle>(p.shape)) {
            loose_triangles[p.visibility].push_back(i);
        } else {
            user.visibility |= p.visibility;
            user.primitives.push_back(i);
            s.user_bounds.push_back(b);
        }
    }
    for (auto& [visibility, members] : loose_triangles)
        s.geometries.push_back({Scene::Kind::triangles, visibility, 0, std::move(members)});
    if (!user.primitives.empty()) s.geometries.push_back(std::move(user));

    const std::lock_guard lock(build_mutex());
    const std::int64_t bytes_before = embree_live_bytes;
    first_error.clear();
    rtcGetDeviceError(device().handle);  // forget errors from before this build
    s.handle = rtcNewScene(device().handle);
    check("creating a scene");
    rtcSetSceneFlags(s.handle, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s.handle, quality == EmbreeBuildQuality::high
                                          ? RTC_BUILD_QUALITY_HIGH
                                          : RTC_BUILD_QUALITY_MEDIUM);

    std::unordered_map<const MeshData*, std::size_t> copy_of;  // shared meshes are copied once
    for (unsigned id = 0; id < s.geometries.size(); ++id) {
        const Scene::Geometry& g = s.geometries[id];
        if (g.kind == Scene::Kind::mesh) {
            const MeshData& mesh = *std::get<TriangleMesh>(primitives[g.primitive].shape).data;
            const auto [it, added] = copy_of.try_emplace(&mesh, s.vertices.size());
            if (added) s.vertices.push_back(padded_copy(mesh.positions));
            attach_triangles(s.handle, id, g, s.vertices[it->second].data(), mesh.positions.size(),
                             mesh.triangles.front().data(), mesh.triangles.size());
        } else if (g.kind == Scene::Kind::triangles) {
            std::vector<Point3> corners;
            corners.reserve(3 * g.primitives.size());
            for (const std::uint32_t i : g.primitives)
                for (const Point3 v : std::get<Triangle>(primitives[i].shape).vertices)
                    corners.push_back(v);
            std::vector<std::uint32_t>& index = s.indices.emplace_back(corners.size());
            for (std::uint32_t k = 0; k < index.size(); ++k) index[k] = k;
            s.vertices.push_back(padded_copy(corners));
            attach_triangles(s.handle, id, g, s.vertices.back().data(), corners.size(),
                             index.data(), g.primitives.size());
        } else {
            attach_user(s.handle, id, s);
        }
    }
    rtcCommitScene(s.handle);
    check("building the scene");
    s.embree_bytes = std::size_t(std::max<std::int64_t>(0, embree_live_bytes - bytes_before));
}

EmbreeAggregate::~EmbreeAggregate() = default;

namespace {

// The glint hit of Embree's hit on geometry geom_id: a mesh's part is its triangle, as
// TriangleMesh::intersect says; a user primitive's hit is glint's own.
Hit hit_of(const Scene& scene, unsigned geom_id, unsigned prim_id, float t, float u, float v,
           const ShapeHit& user_hit) {
    Hit hit{{}, scene.primitive_of(geom_id, prim_id)};
    switch (scene.geometries[geom_id].kind) {
        case Scene::Kind::mesh:
            hit.shape_hit = {t, u, v, prim_id};
            break;
        case Scene::Kind::triangles:
            hit.shape_hit = {t, u, v};
            break;
        case Scene::Kind::user:
            hit.shape_hit = user_hit;
            break;
    }
    return hit;
}

// Embree traces only in front of the origin, and asserts on an empty range.
bool embree_range(Interval& range) {
    range.min = std::max(range.min, 0.0f);
    return range.min <= range.max;
}

}  // namespace

std::optional<Hit> EmbreeAggregate::closest_unbounded(const Ray& ray, std::uint32_t ray_mask,
                                                      Interval& t_range) const {
    std::optional<Hit> closest;
    for (const std::uint32_t index : unbounded_) {
        const Primitive& p = primitives_[index];
        if ((p.visibility & ray_mask) == 0) continue;
        if (const auto hit = glint::intersect(p.shape, ray, t_range)) {
            const Hit candidate{*hit, index};
            if (!closest || nearer(candidate, *closest)) closest = candidate;
            t_range.max = closest->shape_hit.t;
        }
    }
    return closest;
}

bool EmbreeAggregate::any_unbounded(const Ray& ray, std::uint32_t ray_mask,
                                    Interval t_range) const {
    for (const std::uint32_t index : unbounded_) {
        const Primitive& p = primitives_[index];
        if ((p.visibility & ray_mask) != 0 && glint::intersect(p.shape, ray, t_range)) return true;
    }
    return false;
}

std::optional<Hit> EmbreeAggregate::closest_hit(const Ray& ray, Interval t_range,
                                                std::uint32_t ray_mask) const {
    std::optional<Hit> closest = closest_unbounded(ray, ray_mask, t_range);
    if (!embree_range(t_range)) return closest;
    QueryContext context(*scene_, false);
    context.carry(0, ray);
    RTCRayHit rayhit;
    rayhit.ray = {ray.origin.x,
                  ray.origin.y,
                  ray.origin.z,
                  t_range.min,
                  ray.direction.x,
                  ray.direction.y,
                  ray.direction.z,
                  0,
                  t_range.max,
                  ray_mask,
                  0,
                  0};
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_->handle, &context.embree, &rayhit);
    const unsigned geom_id = rayhit.hit.geomID;
    if (geom_id == RTC_INVALID_GEOMETRY_ID) return closest;
    const Hit hit = hit_of(*scene_, geom_id, rayhit.hit.primID, rayhit.ray.tfar, rayhit.hit.u,
                           rayhit.hit.v, context.user_hit[0]);
    if (!closest || nearer(hit, *closest)) closest = hit;
    return closest;
}

bool EmbreeAggregate::any_hit(const Ray& ray, Interval t_range, std::uint32_t ray_mask) const {
    if (any_unbounded(ray, ray_mask, t_range)) return true;
    if (!embree_range(t_range)) return false;
    QueryContext context(*scene_, false);
    context.carry(0, ray);
    RTCRay r{ray.origin.x,
             ray.origin.y,
             ray.origin.z,
             t_range.min,
             ray.direction.x,
             ray.direction.y,
             ray.direction.z,
             0,
             t_range.max,
             ray_mask,
             0,
             0};
    rtcOccluded1(scene_->handle, &context.embree, &r);
    return r.tfar < 0;  // Embree sets tfar to -inf when the ray is blocked
}

namespace {

// Lane i of an Embree packet of eight set to the ray over range.
void set_lane(RTCRay8& r, std::size_t i, const Ray& ray, Interval range, std::uint32_t ray_mask) {
    r.org_x[i] = ray.origin.x;
    r.org_y[i] = ray.origin.y;
    r.org_z[i] = ray.origin.z;
    r.tnear[i] = range.min;
    r.dir_x[i] = ray.direction.x;
    r.dir_y[i] = ray.direction.y;
    r.dir_z[i] = ray.direction.z;
    r.time[i] = 0;
    r.tfar[i] = range.max;
    r.mask[i] = ray_mask;
    r.id[i] = 0;
    r.flags[i] = 0;
}

}  // namespace

void EmbreeAggregate::closest_hits(std::span<const Ray> rays, Interval t_range,
                                   std::uint32_t ray_mask, std::optional<Hit>* hits) const {
    static_assert(kRayPacketSize == 8, "rtcIntersect8");
    QueryContext context(*scene_, true);
    alignas(32) RTCRayHit8 rayhit{};
    alignas(32) int valid[8] = {};
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Interval range = t_range;
        hits[i] = closest_unbounded(rays[i], ray_mask, range);
        if (!embree_range(range)) continue;
        valid[i] = -1;
        set_lane(rayhit.ray, i, rays[i], range, ray_mask);
        rayhit.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rayhit.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        context.carry(i, rays[i]);
    }
    rtcIntersect8(valid, scene_->handle, &context.embree, &rayhit);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const unsigned geom_id = rayhit.hit.geomID[i];
        if (valid[i] == 0 || geom_id == RTC_INVALID_GEOMETRY_ID) continue;
        const Hit hit = hit_of(*scene_, geom_id, rayhit.hit.primID[i], rayhit.ray.tfar[i],
                               rayhit.hit.u[i], rayhit.hit.v[i], context.user_hit[i]);
        if (!hits[i] || nearer(hit, *hits[i])) hits[i] = hit;
    }
}

unsigned EmbreeAggregate::any_hits(std::span<const Ray> rays, const Interval* t_ranges,
                                   std::uint32_t ray_mask) const {
    QueryContext context(*scene_, true);
    alignas(32) RTCRay8 ray{};
    alignas(32) int valid[8] = {};
    unsigned blocked = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Interval range = t_ranges[i];
        if (any_unbounded(rays[i], ray_mask, range)) {
            blocked |= 1u << i;
            continue;
        }
        if (!embree_range(range)) continue;
        valid[i] = -1;
        set_lane(ray, i, rays[i], range, ray_mask);
        context.carry(i, rays[i]);
    }
    rtcOccluded8(valid, scene_->handle, &context.embree, &ray);
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (valid[i] != 0 && ray.tfar[i] < 0) blocked |= 1u << i;
    return blocked;
}

std::size_t EmbreeAggregate::memory_bytes() const {
    std::size_t bytes = sizeof(*this) + sizeof(Scene) + scene_->embree_bytes +
                        unbounded_.capacity() * sizeof(std::uint32_t) +
                        scene_->user_bounds.capacity() * sizeof(Bounds3) +
                        scene_->geometries.capacity() * sizeof(Scene::Geometry);
    for (const Scene::Geometry& g : scene_->geometries)
        bytes += g.primitives.capacity() * sizeof(std::uint32_t);
    for (const auto& v : scene_->vertices) bytes += v.capacity() * sizeof(float);
    for (const auto& i : scene_->indices) bytes += i.capacity() * sizeof(std::uint32_t);
    return bytes;
}

AccelStats EmbreeAggregate::statistics() const {
    AccelStats stats;
    stats.available = false;
    stats.unbounded = unbounded_.size();
    stats.memory_bytes = memory_bytes();
    return stats;
}

}  // namespace glint
