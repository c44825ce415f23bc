// glint's own POV-Ray test scene for the basic shapes: cylinder (open and closed), cone, torus,
// disc with a hole, triangle, smooth_triangle and polygons (one of three outlines: a frame
// round a hole and an island), with transforms. Its reference,
// shapes-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Ishapes.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <-6, 12, -8> color rgb 1 }
light_source { <8, 6, -4> color rgb 0.3 }
plane { y, -1 pigment { rgb 0.7 } }
cylinder { <-3, -1, 1>, <-3, 1, 1>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
cylinder { <-1.5, -1, 2>, <-1.5, 1.2, 2>, 0.5 open pigment { rgb <0.2, 0.6, 0.9> } }
cone { <0, -1, 1>, 0.8, <0, 1, 1>, 0.1 pigment { rgb <0.3, 0.8, 0.3> } }
torus { 0.7, 0.25 rotate x * 60 translate <2.5, 0, 1> pigment { rgb <0.9, 0.8, 0.2> } }
disc { <-2.5, -0.5, -2>, <0, 1, -0.3>, 0.8, 0.3 pigment { rgb <0.8, 0.4, 0.9> } }
triangle { <-0.8, -1, -2>, <0.8, -1, -2>, <0, 0.6, -2.5> pigment { rgb <1, 0.6, 0.3> } }
smooth_triangle { <1.5, -1, -2>, <0, 0, -1>, <3, -1, -2>, <1, 0, -1>, <2.2, 0.6, -2.4>, <0, 1, -1> pigment { rgb <0.4, 0.9, 0.8> } }
polygon { 5, <0, 0>, <1, 0>, <1, 1>, <0.5, 1.5>, <0, 1> scale 0.8 rotate x * -70 translate <3.5, -0.9, -1.5> pigment { rgb <0.9, 0.9, 0.9> } }
// A frame of two outlines, each closed by its first point, and an island in its hole.
polygon { 15, <0, 0>, <1.6, 0>, <1.6, 1.6>, <0, 1.6>, <0, 0>, <0.4, 0.4>, <1.2, 0.4>, <1.2, 1.2>, <0.4, 1.2>, <0.4, 0.4>, <0.7, 0.7>, <0.9, 0.7>, <0.9, 0.9>, <0.7, 0.9>, <0.7, 0.7> scale 1.5 rotate y * -15 translate <2.6, -1, 3> pigment { rgb <0.9, 0.3, 0.4> } }
