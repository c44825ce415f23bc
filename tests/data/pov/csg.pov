// glint's own POV-Ray test scene for CSG: union, merge, intersection and difference of
// spheres, boxes and cylinders, transformed as wholes. Its reference, csg-povray.png, is
// POV-Ray 3.7.0.10's render at 160x120 without antialiasing: povray +Icsg.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.85 rgb 0.5 } }
union { sphere { 0, 0.7 } box { <-0.4, -1, -0.4>, <0.4, 0.3, 0.4> } pigment { rgb <0.9, 0.3, 0.2> } translate <-3, 0, 0> }
merge { sphere { <-0.3, 0, 0>, 0.6 } sphere { <0.3, 0, 0>, 0.6 } pigment { rgb <0.3, 0.5, 0.9> } translate <-1, 0, 0> }
intersection { box { -0.8, 0.8 } sphere { 0, 1.05 } pigment { rgb <0.3, 0.8, 0.3> } rotate y * 30 translate <1, 0, 0> }
difference { box { -0.8, 0.8 } cylinder { <0, 0, -1>, <0, 0, 1>, 0.5 } cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5 } pigment { rgb <0.9, 0.8, 0.3> } rotate <0, -30, 0> translate <3, 0, 0> }
