// error: 2:1: lathe: a cubic spline needs at least 4 points, got 3
lathe { cubic_spline 3, <1, 0>, <1, 1>, <0.5, 2> }
