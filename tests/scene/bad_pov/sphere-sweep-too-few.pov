// error: 2:1: sphere_sweep b_spline needs at least 4 spheres, got 3
sphere_sweep { b_spline 3, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 1, 0>, 1 }
