// error: 2:1: cylinder top must differ from its base
cylinder { <0, 1, 0>, <0, 1, 0>, 0.5 }
