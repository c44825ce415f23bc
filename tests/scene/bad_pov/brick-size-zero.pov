// error: 2:51: brick_size must be > 0 on every axis
box { 0, 1 pigment { brick rgb 1 rgb 0 brick_size <1, 0, 1> } }
