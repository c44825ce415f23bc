// error: 2:17: comment is not closed: /* without */
sphere { 0, 1 } /* the end
