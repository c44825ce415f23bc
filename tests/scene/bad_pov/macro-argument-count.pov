// error: 4:1: macro "Ball" takes 2 arguments, got 1
// note: it is defined at
#macro Ball(C, R) sphere { C, R } #end
Ball(<0, 1, 0>)
