// Acceleration structures by name: the table behind --accel and glint bench.
#include "glint/accel/make_aggregate.h"

#include "glint/accel/bvh_aggregate.h"
#include "glint/accel/grid_aggregate.h"
#include "glint/accel/kdtree_aggregate.h"
#include "glint/accel/primitive_list.h"

#ifdef GLINT_HAVE_EMBREE
#include "glint/accel/embree_aggregate.h"
#endif

namespace glint {

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives) {
    switch (kind) {
        case AccelKind::list:
            return std::make_unique<PrimitiveList>(primitives);
        case AccelKind::bvh:
            return std::make_unique<BvhAggregate>(primitives);
        case AccelKind::grid:
            return std::make_unique<GridAggregate>(primitives);
        case AccelKind::kdtree:
            return std::make_unique<KdTreeAggregate>(primitives);
#ifdef GLINT_HAVE_EMBREE
        case AccelKind::embree:
            return std::make_unique<EmbreeAggregate>(primitives);
#endif
    }
    return nullptr;
}

namespace {
// One row per structure: a new one adds its row here and its case above.
struct Named {
    std::string_view name;
    AccelKind kind;
};
constexpr Named kStructures[] = {
    {"bvh", AccelKind::bvh},       {"grid", AccelKind::grid},
    {"kdtree", AccelKind::kdtree}, {"list", AccelKind::list},
#ifdef GLINT_HAVE_EMBREE
    {"embree", AccelKind::embree},
#endif
};
}  // namespace

std::string_view accel_name(AccelKind kind) {
    for (const Named& s : kStructures)
        if (s.kind == kind) return s.name;
    return "unknown";
}

std::optional<AccelKind> accel_from_name(std::string_view name) {
    for (const Named& s : kStructures)
        if (s.name == name) return s.kind;
    return std::nullopt;
}

std::vector<std::string_view> accel_names() {
    std::vector<std::string_view> names;
    for (const Named& s : kStructures) names.push_back(s.name);
    return names;
}

}  // namespace glint
