#version 3.7;
#fopen F "data.txt" write
#write (F, "\"label\",", 2.5, ",", <1, 2, 3>, "\n")
#fclose F
#fopen F "data.txt" read
#while (defined(F)) #read (F, S, N, V) #end
#fclose F
#fopen G "part.inc" write #write (G "#declare R = 0.5;") #fclose G
#include "part.inc"
#declare A = array[2]; #declare A[1] = 1;
#ifdef (A[1]) sphere { V, R pigment { rgb <N, 0, 0> } } #end
#declare B = box { -1, 1 translate x }
#declare Lo = min_extent(B); #declare Hi = max_extent(B);
#declare M = material { texture { pigment { rgbt <1, 1, 1, 0.5> } } interior { ior 1.3 } }
sphere { Lo, 0.5 material { M } }
plane { y, -1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
camera { location <0, 1, -5> look_at Hi }
light_source { <5, 5, -5> color rgb 1 }
