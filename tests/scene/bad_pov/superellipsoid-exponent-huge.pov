// error: 2:18: superellipsoid's e and n must be in [0.001, 1000]
superellipsoid { <1, 1e9> }
