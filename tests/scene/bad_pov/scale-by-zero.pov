// error: 2:13: scale by zero flattens the object: every factor must be non-zero
box { -1, 1 scale <1, 0, 1> }
