// glint's own POV-Ray test scene for finishes: ambient, diffuse, phong and phong_size,
// specular and roughness, brilliance, metallic and reflection, on a row of spheres. Its
// reference, finishes-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without
// antialiasing: povray +Ifinishes.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -7> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-3, 0, 0>, 0.8 pigment { rgb <0.9, 0.2, 0.2> } finish { ambient 0.3 diffuse 0.5 phong 0.9 phong_size 60 } }
sphere { <-1, 0, 0>, 0.8 pigment { rgb <0.2, 0.8, 0.3> } finish { specular 0.7 roughness 0.02 } }
sphere { <1, 0, 0>, 0.8 pigment { rgb <0.3, 0.4, 0.9> } finish { brilliance 4 diffuse 0.9 } }
sphere { <3, 0, 0>, 0.8 pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0 diffuse 0.3 phong 0.8 metallic reflection 0.5 } }
