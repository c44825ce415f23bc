// error: 3:31: expected a float as mandel's iterations, got an object or texture
// mandel needs its most iterations.
plane { y, 0 pigment { mandel color_map { [0 rgb 0] [1 rgb 1] } } }
