// error: 2:1: prism: too few points: the spline's segment from point 5 needs point 7, but there are 6
prism { quadratic_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <2, 2>, <3, 3> }
