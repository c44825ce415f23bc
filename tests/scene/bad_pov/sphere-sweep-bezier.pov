// error: 2:16: expected linear_spline, b_spline or cubic_spline in sphere_sweep, got "bezier_spline"
sphere_sweep { bezier_spline 4, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1, <3, 0, 0>, 1 }
