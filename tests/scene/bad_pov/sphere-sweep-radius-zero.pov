// error: 2:58: sphere_sweep radius must be > 0, got 0
sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 0 }
