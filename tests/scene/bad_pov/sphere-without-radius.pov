// error: 2:20: expected a value, got '}'
sphere { <0, 0, 0> }
