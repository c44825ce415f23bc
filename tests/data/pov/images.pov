// glint's own POV-Ray test scene for image_map: grid.png (16 x 8 pixels) projected planar and
// repeated on the floor, planar once and interpolated on a turned box, spherical on a sphere,
// cylindrical once on a cylinder, and spherical interpolated on a turned sphere. Its reference,
// images-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Iimages.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { image_map { png "grid.png" interpolate 2 } scale 6 rotate x * 90 } }
box { <0, 0, 0>, <0.98, 0.98, 0.2> pigment { image_map { png "grid.png" once interpolate 2 } } scale 1.6 rotate y * -20 translate <-3.2, 0, 0> }
sphere { <0, 0, 0>, 1 pigment { image_map { png "grid.png" map_type 1 } } rotate y * 30 translate <-0.6, 1, 0.5> }
cylinder { <0, 0, 0>, <0, 0.98, 0>, 0.8 pigment { image_map { png "grid.png" map_type 2 once } } scale <1, 1.8, 1> translate <2.2, 0, 0.5> }
sphere { <0, 0, 0>, 0.6 pigment { image_map { png "grid.png" map_type 1 interpolate 2 } } rotate <30, 60, 0> translate <1, 0.6, -2> }
