// glint's own POV-Ray test scene for polynomial surfaces: a quartic torus bounded by a sphere,
// a quadric ellipsoid clipped by a box, and a poly cylinder cut by an intersection's box. Its
// reference, polynomials-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without
// antialiasing: povray +Ipolynomials.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.4 } }
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 1.5, 0, 0, 0, 0, 1, 0, -2.5, 0, 0.390625>
  sturm
  bounded_by { sphere { 0, 1.6 } }
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.6 }
  rotate x * 60 translate <-2, 0.5, 0>
}
quadric { <1, 4, 1>, <0, 0, 0>, <0, 0, 0>, -1
  clipped_by { box { <-2, -2, -2>, <2, 2, 0.3> } }
  pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.4 }
  translate <0.5, 0, 1>
}
intersection {
  poly { 2, <1, 0, 0, 0, 0, 0, 0, 1, 0, -0.36> }
  box { <-1, -1, -1>, <1, 2, 1> }
  pigment { rgb <0.4, 0.8, 0.3> }
  translate <2.5, 0, 0>
}
