; expect: 3:1: incremental positioning (G91) is not supported
G43.4 H1
G91 X1.
