// error: 4:3: clipped_by needs objects inside it
sphere { 0, 1
  pigment { rgb 1 }
  clipped_by { }
}
