// error: 2:15: matrix has no inverse: it flattens the object
sphere { 0, 1 matrix <1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0> }
