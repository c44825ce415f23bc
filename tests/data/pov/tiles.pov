// glint's own POV-Ray test scene: the brick and hexagon patterns on walls and spheres, with
// their default colours and colours of their own, brick_size and mortar. Its reference,
// tiles-povray.png, is POV-Ray 3.7's render of this file (README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 1, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { color rgb 0.6 } }
box { <-4, 0, 1>, <0, 3, 1.5> pigment { brick color rgb 0.7, color rgb <0.6, 0.2, 0.1> brick_size <1, 0.7, 0.6> mortar 0.08 } }
box { <0.2, 0, 1>, <4, 3, 1.5> pigment { hexagon color rgb <0.9, 0.8, 0.2>, color rgb <0.2, 0.5, 0.8> color rgb 0.9 scale 0.5 rotate x * -90 } }
sphere { <-2, 1, -2>, 1 pigment { brick scale 0.1 } }
sphere { <2, 1, -2>, 1 pigment { hexagon scale 0.25 rotate x * 90 } }
