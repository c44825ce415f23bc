// error: 2:1: sor: heights must rise along the curve: point 3 is not above point 2
sor { 4, <1, 0>, <1, 1>, <1, 0.5>, <1, 2> }
