// error: 2:25: pigment pattern "uv_mapping" is not supported yet
sphere { 0, 1 pigment { uv_mapping gradient x } }
