// error: 2:41: cannot find the image "no-such-image.png"
sphere { 0, 1 pigment { image_map { png "no-such-image" } } }
