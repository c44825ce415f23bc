// error: 2:1: #if is not closed by #end
#if (1)
sphere { 0, 1 }
