// error: 2:10: "Centre" is not declared
sphere { Centre, 1 }
