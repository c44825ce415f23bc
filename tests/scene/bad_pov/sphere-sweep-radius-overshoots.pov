// error: 2:1: sphere_sweep's radius must be > 0 along its path, got -0.009436
sphere_sweep { cubic_spline 4, <0, 0, 0>, 10, <1, 0, 0>, 0.01, <2, 0, 0>, 0.01, <3, 0, 0>, 10 }
