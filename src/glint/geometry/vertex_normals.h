// Smooth vertex normals for meshes that have none (or whose normals are to be replaced), with
// creases kept sharp by an angle threshold.
#pragma once

#include "glint/geometry/triangle_mesh.h"

namespace glint {

// Replaces the normals with smooth vertex normals that respect creases (as 3ds Max and Assimp's
// smoothing do): each triangle corner gets the average of the normals of the faces around its
// vertex position whose normals differ from its own face's by less than the crease angle,
// weighted by the faces' angles at that vertex (Thuermer and Wuethrich 1998, "Computing vertex
// normals from polygonal facets"). Vertices on sharper edges are split, one copy per distinct
// normal; vertices at the same position count as one, so uv seams do not show in the shading.
// Vertices that no triangle uses are dropped. Call before build_mesh, on valid indices.
// Angle 0 gives flat shading, 180 smooths everything.
void compute_vertex_normals(MeshData& mesh, float crease_angle_degrees);

}  // namespace glint
