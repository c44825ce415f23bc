// error: 2:20: expected ',' after the sphere's centre, got the number 1
sphere { <0, 0, 0> 1 }
