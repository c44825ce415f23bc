// glint's own POV-Ray test scene: text in three TrueType fonts, with kerning, an offset between
// letters, and a letter carved out of a box by a difference. Its reference, text-povray.png, is
// POV-Ray 3.7's render of this file (README.md); the fonts lie beside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.8, 2, -5> look_at <1.8, 0.3, -0.6> angle 55 }
light_source { <-3, 6, -6> color rgb 1 }
light_source { <4, 2, -3> color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.3> }
plane { y, -0.01 pigment { checker color rgb 0.8 color rgb 0.5 } }
text { ttf "timrom.ttf" "Glint ok" 0.3, 0
  pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 }
  rotate x * 20 translate <-0.2, 0.2, 0> }
text { ttf "cyrvetic" "AVo%" 0.2, <0.05, 0.02, 0>
  pigment { color rgb <0.2, 0.6, 0.9> } finish { specular 0.5 roughness 0.02 }
  scale 0.8 translate <0.8, 0, -1.2> }
difference {
  box { <2.6, 0, -1.8>, <3.6, 0.8, -1.6> }
  text { ttf "crystal.ttf" "e" 1, 0 scale 0.9 translate <2.85, 0.1, -1.9> }
  pigment { color rgb <0.9, 0.8, 0.2> } }
