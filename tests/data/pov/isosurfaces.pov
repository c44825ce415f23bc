// Isosurfaces: functions of x, y and z with POV-Ray's operators and built-in functions,
// functions.inc's f_rounded_box and f_torus, a declared function with parameters, a threshold,
// closed and open containers (a box and a sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"

camera { location <0, 3, -9> look_at <0, 0.3, 0> angle 45 }
light_source { <-10, 20, -15> color rgb 1 }
light_source { <10, 5, -20> color rgb 0.3 }
plane { y, -1.2 pigment { checker rgb 0.8, rgb 0.6 } }

#declare Fin = finish { ambient 0.15 diffuse 0.8 specular 0.4 roughness 0.02 }
#declare Bump = function(a, b, c, k) { a*a + c*c - k*b }

// A cylinder in its box: closed, so the box's faces cap it.
isosurface {
  function { sqrt(x*x + z*z) - 0.8 }
  contained_by { box { -1, 1 } }
  pigment { rgb <0.9, 0.3, 0.2> } finish { Fin }
  translate <-3, 0, 1>
}

// Ripples over a plane, open.
isosurface {
  function { y - 0.2*sin(4*x)*cos(4*z) }
  contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
  open
  max_gradient 3
  pigment { rgb <0.2, 0.5, 0.9> } finish { Fin }
  translate <0, -0.5, 1.5>
}

// functions.inc's rounded box and torus.
isosurface {
  function { f_rounded_box(x, y, z, 0.25, 0.8, 0.6, 0.8) }
  contained_by { box { -1, 1 } }
  pigment { rgb <0.3, 0.8, 0.3> } finish { Fin }
  rotate 30*y translate <3, 0, 1>
}
isosurface {
  function { f_torus(x, y, z, 0.7, 0.25) }
  contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } }
  pigment { rgb <0.9, 0.8, 0.2> } finish { Fin }
  rotate -60*x translate <-1.5, 0.2, -1.5>
}

// A declared function with parameters and a threshold, in a sphere: the paraboloid's cap.
isosurface {
  function { Bump(x, y, z, 2) + pow(abs(x), 3) }
  threshold 0.3
  max_gradient 5
  contained_by { sphere { 0, 1 } }
  pigment { rgb <0.8, 0.4, 0.9> } finish { Fin }
  translate <1.5, 0, -1.5>
}
