// glint's own POV-Ray test scene for inverse: a box with a square hole (intersection with an
// inverse box) and a sphere's lower half (difference with an inverse plane). Its reference,
// inverse-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Iinverse.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 3, -5> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } }
intersection { box { -1, 1 } box { <-0.7, -2, -0.7> <0.7, 2, 0.7> inverse } pigment { rgb <0.9, 0.4, 0.2> } }
difference { sphere { <0, 1.3, 0>, 0.6 } plane { y, 1.3 inverse } pigment { rgb <0.2, 0.5, 0.9> } }
