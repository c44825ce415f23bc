// error: 2:33: text thickness must not be 0
text { ttf "timrom.ttf" "glint" 0, 0 }
