// error: 2:40: "importance" is not a radiosity setting
global_settings { radiosity { count 50 importance 0.5 } }
sphere { 0, 1 pigment { rgb 1 } }
