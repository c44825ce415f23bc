// glint's own POV-Ray test scene for fog: constant fog over a long checkered floor and a row of
// spheres fading into it, and a band of ground fog (fog_type 2) lying on the floor. Its
// reference, fog-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without antialiasing:
// povray +Ifog.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 10> angle 60 }
light_source { <-10, 20, -10> color rgb 1 }
background { rgb <0.1, 0.2, 0.5> }
fog { distance 25 color rgb <0.7, 0.75, 0.8> }
fog { fog_type 2 distance 3 color rgbt <0.9, 0.9, 0.9, 0.2> fog_offset 0.2 fog_alt 0.4 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } finish { ambient 0.2 diffuse 0.8 } }
#for (I, 0, 5)
  sphere { <-3 + 1.2 * I, 1, 2 + 6 * I>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
#end
