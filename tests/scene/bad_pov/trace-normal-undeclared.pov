// error: 3:46: trace's fourth argument must be a vector declared before, which takes the normal; got "Normal"
#declare Ground = plane { y, 0 }
#declare Spot = trace(Ground, <0, 5, 0>, -y, Normal);
sphere { Spot, 1 pigment { rgb 1 } }
