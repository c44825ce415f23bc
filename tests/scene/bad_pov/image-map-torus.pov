// error: 2:58: map_type 5 is not supported yet: glint projects images planar (0), spherical (1) and cylindrical (2)
sphere { 0, 1 pigment { image_map { png "pixel" map_type 5 } } }
