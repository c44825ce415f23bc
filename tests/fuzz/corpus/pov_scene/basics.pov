// glint's own POV-Ray test scene: a camera with look_at and angle, a point light, a checkered
// plane, a reflective sphere with a phong highlight, a declared box placed by object { } with
// rotate and translate, and a CSG difference. Its reference, basics-povray.png, is POV-Ray
// 3.7.0.10's render at 160x120 without antialiasing: povray +Ibasics.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare White = rgb 1;
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> color White }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker color White, color rgb 0.3 } finish { diffuse 0.8 } }
sphere { <-1, 1, 0>, 1
  pigment { color rgb <1, 0, 0> }
  finish { phong 0.8 phong_size 60 reflection 0.2 }
}
#declare Cube = box { -0.6, 0.6 pigment { color green 1 } }
object { Cube rotate y*30 translate <1.5, 0.6, 0.5> }
difference {
  cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.5 }
  sphere { <0, 1.2, 0>, 0.45 }
  pigment { rgb <1, 1, 0> }
  translate <0.2, 0, -1.5>
}
