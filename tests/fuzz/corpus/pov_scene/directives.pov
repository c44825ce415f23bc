#include "shapes.inc"
#declare A = array[3] { 1, 2, 3 };
#local I = 0;
#while (I < 3)
  #switch (A[I])
    #case (1) sphere { <I, 0, 0>, 0.3 } #break
    #range (2, 3) object { Ball scale 0.1 translate x * Twice(I) }
  #end
  #local I = I + 1;
#end
#for (J, 0, 2) box { <J, 1, 0>, <J + 0.5, 1.5, 0.5> pigment { rgb <J / 2, 0, 1> } } #end
#macro Col(R) rgb <R, 1 - R, 0.5> #end
#if (version >= 3.7 & strlen(str(pi, 0, 3)) = 5)
  light_source { <0, 10, -5> color Col(0.3) }
#else
  #error "no"
#end
camera { location <0, 1, -6> look_at 0 angle 40 }
