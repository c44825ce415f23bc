// error: 2:47: mortar must be >= 0
box { 0, 1 pigment { brick rgb 1 rgb 0 mortar -0.5 } }
