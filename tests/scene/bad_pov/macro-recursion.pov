// error: 2:18: macros nest deeper than 200 calls (endless recursion?)
#macro Deeper(N) Deeper(N + 1) #end
#declare A = Deeper(0);
