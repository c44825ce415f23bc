#include "glint/accel/make_aggregate.h"

#include "glint/accel/bvh_aggregate.h"
#include "glint/accel/primitive_list.h"

namespace glint {

std::unique_ptr<Aggregate> make_aggregate(AccelKind kind, std::span<const Primitive> primitives) {
    switch (kind) {
        case AccelKind::list:
            return std::make_unique<PrimitiveList>(primitives);
        case AccelKind::bvh:
            return std::make_unique<BvhAggregate>(primitives);
    }
    return nullptr;
}

}  // namespace glint
