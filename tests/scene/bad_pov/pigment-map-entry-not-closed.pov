// error: 3:58: expected ']' after the pigment, got '}'
// A pigment_map entry missing its ']'.
plane { y, 0 pigment { gradient y pigment_map { [0 rgb 1 } } }
