// error: 2:61: interpolate must be 2, 3 or 4
sphere { 0, 1 pigment { image_map { png "pixel" interpolate 1 } } }
