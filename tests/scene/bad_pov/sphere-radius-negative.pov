// error: 2:21: sphere radius must be > 0, got -2
sphere { <0, 1, 0>, -2 }
