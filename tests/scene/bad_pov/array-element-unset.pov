// error: 3:13: element of "A" is read before it is given a value
#declare A = array[2];
sphere { 0, A[1] }
