// glint's own POV-Ray test scene for mesh2: a pyramid with its normals shared by index, and a
// square with uvs by their own indices and a texture a face from its texture_list. Its
// reference, mesh2-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Imesh2.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 } }
mesh2 {
  vertex_vectors { 5, <0, 2, 0>, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }
  normal_vectors { 5, <0, 1, 0>, <-1, 0.5, -1>, <1, 0.5, -1>, <1, 0.5, 1>, <-1, 0.5, 1> }
  face_indices { 4, <0, 1, 2>, <0, 2, 3>, <0, 3, 4>, <0, 4, 1> }
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.6 }
  translate x * -1.5
}
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  texture_list { 2, texture { pigment { rgb <1, 0.9, 0.3> } } texture { pigment { rgb <0.2, 0.3, 0.6> } } }
  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 1 }
  uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { rgb <0.3, 0.6, 0.9> }
  rotate y * 20 translate <0.8, 0.2, 0>
}
