// error: 2:17: unexpected character '@'
sphere { 0, 1 } @
