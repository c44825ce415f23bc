// glint's own POV-Ray test scene for refraction: a glass sphere (ior 1.5) and a water-like sphere
// (ior 1.33), both transmitting, over a checkered floor. Its reference,
// refraction-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Irefraction.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 5, -6> look_at <0, -0.3, 0> angle 50 }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.2 scale 2 } }
background { rgb <0.3, 0.4, 0.6> }
sphere { <-1.3, 0.2, 0>, 1.1 pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 phong 0.8 phong_size 80 } interior { ior 1.5 } }
sphere { <1.4, -0.2, -0.3>, 0.8 pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 } interior { ior 1.33 } }
