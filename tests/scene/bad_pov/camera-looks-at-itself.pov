// error: 2:1: camera look_at is its location
camera { location <0, 1, -3> look_at <0, 1, -3> }
