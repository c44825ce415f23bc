// error: 2:34: gradient direction must not be zero
sphere { 0, 1 pigment { gradient <0, 0, 0> } }
