// glint's own POV-Ray test scene for reflections that vary: kr from a minimum facing the viewer
// to a maximum at grazing incidence by a falloff and by Fresnel's reflectance, a coloured
// reflection, and a metallic one that takes the pigment's colour, on spheres over a checkered
// floor. Its reference, reflections-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without
// antialiasing: povray +Ireflections.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -8> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 8, -7> color rgb 1 }
background { rgb <0.4, 0.5, 0.7> }
plane { y, -1 pigment { checker rgb 0.9 rgb <0.2, 0.3, 0.5> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-3, 0, 0>, 0.9 pigment { rgb 0.1 } finish { ambient 0 diffuse 0.2 reflection { 0.05, 0.9 falloff 2 } } }
sphere { <-1, 0, 0>, 0.9 pigment { rgb <0.1, 0.1, 0.2> } finish { ambient 0 diffuse 0.3 reflection { 0.8 fresnel } } interior { ior 1.5 } }
sphere { <1, 0, 0>, 0.9 pigment { rgb <0.9, 0.6, 0.2> } finish { ambient 0 diffuse 0.2 reflection <0.9, 0.6, 0.2> } }
sphere { <3, 0, 0>, 0.9 pigment { rgb <0.9, 0.5, 0.3> } finish { ambient 0 diffuse 0.2 phong 0.5 reflection { 0.2, 0.8 metallic } } }
