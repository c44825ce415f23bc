// error: 2:41: cannot read the image "image-map-torus.pov": not a PNG, JPEG, HDR, TGA or BMP image stb_image can read (unknown image type)
sphere { 0, 1 pigment { image_map { png "image-map-torus.pov" } } }
