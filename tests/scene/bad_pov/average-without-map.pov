// error: 3:24: average needs a pigment_map
// A pattern averaging nothing.
plane { y, 0 pigment { average color_map { [0 rgb 0] [1 rgb 1] } } }
