// error: 3:16: a vector of 2 components has no .z
#declare UV = <0.5, 0.25>;
sphere { 0, UV.z }
