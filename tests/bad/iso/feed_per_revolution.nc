; expect: 3:1: feed per revolution (G95) is not supported
G43.4 H1
G95
