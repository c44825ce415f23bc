// error: 2:61: precision must be > 0
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr precision 0 }
