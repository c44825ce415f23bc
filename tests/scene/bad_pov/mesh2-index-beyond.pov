// error: 2:1: mesh2 face_indices index 3 is beyond its 3 items
mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 3> } }
