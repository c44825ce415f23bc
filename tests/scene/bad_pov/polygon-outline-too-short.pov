// error: 4:1: polygon: outline 2 has fewer than 3 points
// A square, then an outline of two points closed by repeating the first.
camera { location <0, 0, -5> look_at 0 }
polygon { 7, <0, 0>, <1, 0>, <1, 1>, <0, 0>, <2, 2>, <3, 3>, <2, 2> pigment { rgb 1 } }
