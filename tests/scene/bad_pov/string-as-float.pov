// error: 2:13: expected a float as the sphere's radius, got a string
sphere { 0, "one" }
