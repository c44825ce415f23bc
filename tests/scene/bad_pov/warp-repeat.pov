// error: 2:36: pigment pattern "warp" is not supported yet
sphere { 0, 1 pigment { gradient x warp { repeat x } } }
