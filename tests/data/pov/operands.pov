// glint's own POV-Ray test scene for CSG operands' own textures: a difference whose cut shows
// the taken-away sphere's checker, a union and a merge of two colours, an intersection with a
// texture for the parts without one, a nested difference inside a union, and operands moved
// after their pattern. Its reference, operands-povray.png, is POV-Ray 3.7.0.10's render at
// 160x120 without antialiasing: povray +Ioperands.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 10, -7> color rgb 1 }
plane { y, -1 pigment { rgb 0.7 } }
difference {
  box { -0.8, 0.8 pigment { rgb <0.9, 0.8, 0.3> } }
  sphere { <0, 0.8, -0.8>, 0.7 pigment { checker rgb <0.2, 0.3, 0.9> rgb 1 scale 0.2 } }
  rotate y * -20 translate <-3, 0, 0>
}
union {
  sphere { <-0.3, 0, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
  sphere { <0.3, 0, 0>, 0.6 pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.8 } }
  translate <-1, 0, 0>
}
merge {
  sphere { <-0.3, 0, 0>, 0.6 pigment { rgb <0.3, 0.9, 0.4> } }
  sphere { <0.3, 0, 0>, 0.6 pigment { gradient y color_map { [0 rgb 0.2] [1 rgb <1, 0.6, 0.2>] } scale 0.5 } translate y * 0.2 }
  translate <1, -0.2, -1.8>
}
intersection {
  box { -0.8, 0.8 }
  sphere { 0, 1.05 pigment { rgb <0.8, 0.3, 0.8> } }
  pigment { rgb <0.3, 0.8, 0.3> }
  rotate y * 30 translate <1, 0, 0>
}
union {
  difference {
    cylinder { <0, -1, 0>, <0, 0.6, 0>, 0.7 }
    sphere { <0, 0.6, 0>, 0.5 pigment { rgb <1, 0.2, 0.2> } }
  }
  box { <-0.2, -1, -0.9>, <0.2, 0.2, 0.9> pigment { wood color_map { [0 rgb <0.6, 0.35, 0.1>] [1 rgb <0.9, 0.7, 0.4>] } scale 0.1 } rotate y * 45 }
  pigment { rgb <0.5, 0.8, 0.9> }
  translate <3, 0, 0>
}
