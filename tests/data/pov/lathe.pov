// glint's own POV-Ray test scene: lathes of the four splines, a closed one carved by a
// difference. Its reference, lathe-povray.png, is POV-Ray 3.7's render of this file
// (README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -3> color rgb 0.3 }
background { color rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.55 } }
// A vase of a cubic spline.
lathe { cubic_spline 8, <0, -0.2>, <0.6, 0>, <0.9, 0.6>, <0.5, 1.3>, <0.4, 1.8>, <0.6, 2.2>, <0.65, 2.25>, <0.7, 2.4>
  pigment { color rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } translate <-2.6, 0, 0.5> }
// A bowl of straight pieces, a closed curve, cut by a box.
difference {
  lathe { linear_spline 7, <0, 0>, <1, 0.1>, <1.2, 0.8>, <1.1, 0.8>, <0.9, 0.2>, <0, 0.15>, <0, 0> }
  box { <-2, -1, -2>, <0, 2, 0> }
  pigment { color rgb <0.9, 0.6, 0.2> } finish { phong 0.3 } translate <0, 0, 0.4> }
// A quadratic spline top and a Bezier dome.
lathe { quadratic_spline 6, <0, 0>, <0.8, 0>, <0.3, 0.6>, <0.1, 1.2>, <0.4, 1.6>, <0, 1.7>
  pigment { color rgb <0.3, 0.8, 0.3> } translate <2.4, 0, 0.2> }
lathe { bezier_spline 8, <0.7, 0>, <0.7, 0.39>, <0.39, 0.7>, <0, 0.7>, <0, 0>, <0.2, 0>, <0.5, 0>, <0.7, 0>
  pigment { color rgb <0.9, 0.3, 0.3> } finish { specular 0.6 roughness 0.02 } translate <1.2, 0, -1.6> }
