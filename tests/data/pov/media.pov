// glint's own POV-Ray test scene for media: a sphere of glowing gas whose density falls off
// from its middle (a spherical density with a colour map), a box of absorbing smoke that
// tints what lies behind it, and a hollow sphere of scattering haze lit by the light, its
// shadow on the floor. The planes are hollow: POV-Ray draws no media seen from inside a solid,
// and a plane's inside is its half-space. Its reference, media-povray.png, is POV-Ray
// 3.7.0.10's render at 160x120 without antialiasing: povray +Imedia.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -3> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } hollow }
plane { z, 4 pigment { rgb <0.3, 0.4, 0.6> } hollow }
sphere { 0, 1 pigment { rgbt 1 } hollow
         interior { media { emission <1, 0.5, 0.1> intervals 4 samples 4
                            density { spherical color_map { [0 rgb 0] [1 rgb 2] } } } }
         scale 1.2 translate <-2.2, 0.5, 0> }
box { <-0.8, -0.99, -0.8>, <0.8, 1.2, 0.8> pigment { rgbt 1 } hollow
      interior { media { absorption <0.2, 0.8, 1.2> } } rotate y*30 }
sphere { <2.2, 0.4, 0>, 1.2 pigment { rgbt 1 } hollow
         interior { media { scattering { 1, 0.3 } absorption 0.1 intervals 2 samples 8 } } }
