// error: 2:28: a blob component's radius must be > 0
blob { sphere { <0, 0, 0>, 0, 1 } }
