// glint's own POV-Ray test scene for patterns: a checker turned and scaled, gradient, onion
// (old-style map entries) and radial (frequency, inside a turned union) through colour maps,
// leopard and wood (turned), and a function pattern (mod, floor) all placed by their objects'
// transforms. Its reference,
// patterns-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Ipatterns.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
#declare Stripes = color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <1, 0.9, 0.3>] [0.5 rgb <0.1, 0.2, 0.6>] [1 rgb 1] }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.25 scale 1.5 rotate y*20 } }
sphere { <-2.4, 1, 0>, 1 pigment { gradient y color_map { Stripes } scale 0.5 } }
sphere { <0, 1, 0>, 1 pigment { onion color_map { [0 0.5 color rgb <0,0,1> color rgb 1] [0.5 1 color rgb <1,0.5,0> color rgb 0] } scale 0.4 } translate <0, 0, 0.5> }
union {
  box { <-0.9, 0, -0.9> <0.9, 1.8, 0.9> }
  pigment { radial frequency 6 color_map { [0 rgb 0.1] [0.5 rgb <0.2,0.8,0.3>] [1 rgb 0.1] } }
  rotate y*30 translate <2.4, 0, 0>
}
sphere { <-1.2, 0.5, -2>, 0.5 pigment { leopard color_map { [0 rgb 1] [1 rgb <0.8,0,0>] } scale 0.1 } }
sphere { <1.2, 0.5, -2>, 0.5 pigment { wood color_map { [0 rgb <0.6,0.35,0.1>] [1 rgb <0.9,0.7,0.4>] } scale 0.1 rotate x*70 } }
sphere { <0, 0.4, -2.6>, 0.4 pigment { function { mod(abs(x*3 + y*2), 1) * 0.7 + floor(z*4) * 0.1 } color_map { [0 rgb <0.1,0.1,0.5>] [1 rgb <1,0.8,0.6>] } } }
