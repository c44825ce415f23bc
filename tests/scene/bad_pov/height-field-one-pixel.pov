// error: 2:1: a height_field's image must be at least 2 x 2 pixels
height_field { png "pixel.png" }
