// glint's own POV-Ray test scene for height_field: terrain.png (33 x 33 grey levels, made for
// these tests) flat-shaded and smooth, and a palette image's indices as heights, under
// water_level. Its reference, heightfields-povray.png, is POV-Ray 3.7.0.10's render at 160x120
// without antialiasing: povray +Iheightfields.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
height_field { png "terrain.png" pigment { rgb <0.5, 0.8, 0.4> } translate <-0.5, 0, -0.5> scale <2.5, 1, 2.5> translate <-1.6, 0, 0> }
height_field { png "terrain.png" smooth pigment { rgb <0.8, 0.6, 0.4> } finish { phong 0.5 } translate <-0.5, 0, -0.5> scale <2.5, 1, 2.5> rotate y * 30 translate <1.6, 0, 0.5> }
height_field { png "heights-palette.png" water_level 0.1 pigment { rgb <0.4, 0.5, 0.9> } scale <1.5, 0.5, 1> translate <-0.7, 0, -2.2> }
