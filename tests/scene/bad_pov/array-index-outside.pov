// error: 3:12: index 3 is outside "A"'s 0..2
#declare A = array[3];
#declare A[3] = 1;
