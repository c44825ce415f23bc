// glint's own POV-Ray test scene for coloured glass: a sphere whose filter tints what it lets
// through (and its shadow), a slab that fades by Beer-Lambert's law (fade_power 1001) towards
// its fade_color, and a sphere that fades by POV-Ray's power law, over a checkered floor. Its
// reference, glass-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Iglass.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 4, -7> look_at <0, 0.2, 0> angle 50 }
light_source { <-4, 9, -5> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 scale 1.5 } }
background { rgb <0.5, 0.6, 0.8> }
sphere { <-2, 0, 0>, 1 pigment { rgbf <1, 0.4, 0.2, 0.9> } finish { ambient 0 diffuse 0 phong 0.6 } interior { ior 1.5 } }
box { <-0.6, -0.95, -0.8>, <0.6, 0.9, 0.8> pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 }
      interior { ior 1.2 fade_distance 0.8 fade_power 1001 fade_color <0.2, 0.7, 1> } rotate y*25 }
sphere { <2, 0, 0.2>, 1 pigment { rgbft <0.3, 1, 0.5, 0.4, 0.5> } finish { ambient 0 diffuse 0.1 }
         interior { ior 1.33 fade_distance 1 fade_power 2 fade_color <1, 0.8, 0.3> } }
