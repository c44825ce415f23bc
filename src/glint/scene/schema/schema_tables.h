// The schema tables of each family, which entity_schema.cpp gathers. Internal to glint_scene.
#pragma once

#include <vector>

#include "glint/scene/schema/entity_schema.h"

namespace glint {

std::vector<EntitySchema> shape_schemas();     // the object keys and every shape
std::vector<EntitySchema> light_schemas();     // every light
std::vector<EntitySchema> material_schemas();  // the material, its textures and pattern maps

}  // namespace glint
