// error: 2:142: a face's texture index must be one of texture_list's, 0 to 1 (excluded)
mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0, 1, 2>, 1 } }
