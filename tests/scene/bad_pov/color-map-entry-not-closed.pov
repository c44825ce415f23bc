// error: 2:45: expected ']' after the entry's colour, got '}'
#declare M = color_map { [0 rgb 1] [1 rgb 0 }
