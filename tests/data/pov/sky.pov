// glint's own POV-Ray test scene for sky_sphere: a gradient sky with a half-transparent radial
// layer over it, turned, reflected in a sphere. Its reference, sky-povray.png, is POV-Ray
// 3.7.0.10's render at 160x120 without antialiasing: povray +Isky.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 2, 0> angle 70 }
light_source { <-6, 10, -8> color rgb 1 }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <1, 0.9, 0.7>] [0.3 rgb <0.3, 0.5, 0.9>] [1 rgb <0.05, 0.1, 0.4>] } }
  pigment { radial frequency 8 color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 0.6>] [1 rgbt <1, 1, 1, 1>] } rotate x*10 }
  rotate y*15
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb 0.2 } finish { reflection 0.6 phong 1 } }
