// error: 3:1: #end without an open #if, #while, #for, #switch or #macro
sphere { 0, 1 }
#end
