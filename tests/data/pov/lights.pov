// glint's own POV-Ray test scene for lights: a spotlight with radius and falloff, a parallel
// light, a light with fade_distance and fade_power 2, and a shadowless fill. Its reference,
// lights-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Ilights.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.5 }
camera { location <0, 6, -9> look_at <0, 0, 0> angle 55 }
light_source { <0, 8, 0> color rgb <1, 0.9, 0.8> spotlight point_at <-2, 0, 1> radius 10 falloff 18 }
light_source { <5, 5, -5> color rgb 0.3 parallel point_at 0 }
light_source { <3, 1.5, 1> color rgb <0.4, 0.6, 1> fade_distance 1.5 fade_power 2 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 } }
sphere { <-2, 1, 1>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 } }
box { <1, 0, -1>, <2, 1.5, 0> rotate y * 20 pigment { rgb <0.5, 0.8, 0.4> } finish { ambient 0.05 } }
