// error: 2:54: reflection's falloff must be > 0
sphere { 0, 1 finish { reflection { 0.1, 0.8 falloff 0 } } }
