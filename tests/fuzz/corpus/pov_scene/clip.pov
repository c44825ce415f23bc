// glint's own POV-Ray test scene for clipped_by: a sphere cut open by a plane (a bowl, whose
// inside shows), a box clipped by a sphere and then moved, and a union of two cylinders clipped
// by one box. Its reference, clip-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without
// antialiasing: povray +Iclip.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-4, 10, -6> color rgb 1 }
light_source { <5, 3, -8> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 } }
sphere { 0, 1 clipped_by { plane { y, 0.3 } } pigment { rgb <0.9, 0.5, 0.2> } translate <-2, 0, 0> }
box { -0.8, 0.8 clipped_by { sphere { 0, 1 } } rotate y * 30 translate <0.3, 0, 1> pigment { rgb <0.3, 0.6, 0.9> } }
union {
  cylinder { <0, -1, 0>, <0, 2, 0>, 0.3 translate x * 2 }
  cylinder { <1.5, 0.5, -1>, <2.5, 0.5, 1>, 0.25 }
  clipped_by { box { <1.6, -1, -0.6>, <2.4, 1.4, 0.6> } }
  pigment { rgb <0.4, 0.8, 0.3> }
}
