// error: 2:24: expected read, write or append after #fopen's file name, got "readonly"
#fopen Data "data.txt" readonly
