// error: 6:30: a texture has more than 64 layers
// A texture laid over itself in a loop doubles its layers each time.
#declare T = texture { pigment { rgbt 0.2 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
#declare I = 0;
#while (I < 10)
  #declare T = texture { T } texture { T scale 2 } texture { pigment { rgbf 0.5 } }
  #declare I = I + 1;
#end
sphere { 0, 1 texture { T } }
