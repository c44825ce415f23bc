// error: 2:51: vertex_vectors holds more items than its count, 2
mesh2 { vertex_vectors { 2, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 2> } }
