// error: 2:44: water_level must be in [0, 1]
height_field { png "level.png" water_level 2 }
