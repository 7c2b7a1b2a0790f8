; expect: 3:1: G68 changes the working frame; kin5 does not model frame changes
G43.4 H1
G68 X0 Y0 R45.
