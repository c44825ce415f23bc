// glint's own POV-Ray test scene for the camera: orthographic, with up, right and sky tilted,
// over a grid of boxes. Its reference, camera-povray.png, is POV-Ray 3.7.0.10's render at
// 160x120 without antialiasing: povray +Icamera.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <6, 8, -6> look_at 0 right x * 8 up y * 6 sky <0.2, 1, 0> }
light_source { <-4, 10, -8> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#for (I, -2, 2)
  #for (J, -2, 2)
    box { <-0.35, 0, -0.35>, <0.35, 0.5 + 0.2 * (I + 2), 0.35> translate <I * 1.2, 0, J * 1.2> pigment { rgb <0.5 + 0.1 * I, 0.5, 0.5 - 0.1 * J> } }
  #end
#end
