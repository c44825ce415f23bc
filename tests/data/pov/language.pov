// glint's own POV-Ray test scene for the language: #macro, #while, #for, #switch, #if, arrays,
// rand and seed, vrotate and str/concat in #debug; a ring of spheres whose colours and sizes the
// script computes. Its reference, language-povray.png, is POV-Ray 3.7.0.10's render at 160x120
// without antialiasing: povray +Ilanguage.pov +W160 +H120 -A
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at 0 angle 50 }
light_source { <-5, 10, -5> color rgb 1 }
plane { y, -0.5 pigment { rgb 0.75 } }
#declare Colors = array[3] { <0.9, 0.3, 0.2>, <0.3, 0.8, 0.3>, <0.3, 0.4, 0.9> };
#macro Ball(P, R, C)
  sphere { P, R pigment { rgb C } finish { phong 0.5 } }
#end
#declare S = seed(42);
#declare N = 10;
#declare I = 0;
#while (I < N)
  #declare P = vrotate(<3, 0, 0>, <0, I * 360 / N, 0>);
  #switch (mod(I, 3))
    #case (0) #declare R = 0.5; #break
    #case (1) #declare R = 0.35; #break
    #else #declare R = 0.25 + 0.2 * rand(S);
  #end
  Ball(P, R, Colors[mod(I, 3)])
  #declare I = I + 1;
#end
#for (K, 0, 2)
  #if (K != 1)
    box { <-0.3, -0.5, -0.3>, <0.3, 0.3 + K * 0.5, 0.3> translate <K - 1, 0, 0> pigment { rgb Colors[K] } }
  #end
#end
