// glint's own POV-Ray test scene for the wide cameras: a fisheye of 200 degrees sees a checkered
// floor to its horizon, spheres round it (two a little behind it) and nothing outside its circle.
// Its reference, fisheye-povray.png, is POV-Ray 3.7.0.10's render at 160x120 without
// antialiasing: povray +Ifisheye.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { fisheye location <0, 1, 0> look_at <0, 1, 1> angle 200 }
light_source { <-3, 8, -2> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.8, 0.85, 1>] [1 rgb <0.2, 0.3, 0.8>] } } }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
#declare I = 0;
#while (I < 8)
  sphere { <3, 0.6, 0>, 0.6 rotate y * (I * 45 + 10)
           pigment { rgb <mod(I, 2), I / 7, 1 - I / 7> } finish { phong 0.6 } }
  #declare I = I + 1;
#end
