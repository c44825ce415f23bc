// error: 2:14: rand() takes a stream that seed() made, got 0
#declare R = rand(0);
