// error: 2:13: the number as the sphere's radius must be finite, got inf
sphere { 0, 1/0 }
