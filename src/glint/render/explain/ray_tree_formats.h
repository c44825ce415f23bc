// A ray tree written out: as an indented text a student can read, as JSON (every number as the
// float it is, so that the sample can be recomputed from it exactly; fields in docs/explain.md),
// or as a Graphviz DOT graph.
#pragma once

#include <string>

#include "glint/render/explain/ray_tree.h"

namespace glint {

std::string ray_tree_text(const RayTree& tree);
std::string ray_tree_json(const RayTree& tree);
std::string ray_tree_dot(const RayTree& tree);

}  // namespace glint
