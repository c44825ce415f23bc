// error: 2:52: tightness must be >= 0
light_source { <0, 5, 0> rgb 1 spotlight tightness -3 point_at 0 }
