// error: 2:58: expected '[' or '}' in color_map, got the number 0.5
sphere { 0, 1 pigment { gradient y color_map { [0 rgb 1] 0.5 } } }
