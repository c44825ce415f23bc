// glint's own POV-Ray test scene: prisms of the four splines, linear with a hole, cubic,
// quadratic and Bezier, one of them in a difference. Its reference, prism-povray.png, is POV-Ray
// 3.7's render of this file (README.md).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -6> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.5 } }
// A square frame of straight edges.
prism { linear_sweep linear_spline 0, 0.5, 10,
  <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>,
  <-0.6,-0.6>, <0.6,-0.6>, <0.6,0.6>, <-0.6,0.6>, <-0.6,-0.6>
  pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 }
  translate <-1.6, 0, 0.5> }
// A cubic-spline blob.
prism { cubic_spline 0, 1, 7,
  <0.5, 0.8>, <0,-0.8>, <0.9,0>, <0,0.8>, <-0.9,0>, <0,-0.8>, <0.9,0>
  pigment { color rgb <0.2, 0.6, 0.9> } finish { specular 0.5 roughness 0.02 }
  translate <1.2, 0, 0.8> }
// A quadratic spline leaf, and a Bezier heart, difference of a box.
prism { quadratic_spline -0.2, 0.6, 5,
  <-0.6, -0.6>, <0, -0.8>, <0.7, 0.5>, <-0.7, 0.5>, <0, -0.8>
  pigment { color rgb <0.3, 0.8, 0.3> } translate <0, 0, -1.5> }
difference {
  prism { bezier_spline 0, 0.8, 8,
    <0, -0.7>, <0.9, 0>, <0.6, 0.9>, <0, 0.3>,
    <0, 0.3>, <-0.6, 0.9>, <-0.9, 0>, <0, -0.7>
  }
  box { <-0.2, 0.4, -2>, <0.2, 1, 2> }
  pigment { color rgb <0.9, 0.8, 0.2> } finish { phong 0.4 }
  translate <2, 0, -1.2> }
