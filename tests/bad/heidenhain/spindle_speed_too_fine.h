; expect: 3:17: the spindle speed 0.0101 cannot be written with 3 decimals, the most the controller reads (it would read as another value)
0 BEGIN PGM T MM
1 TOOL CALL 1 Z S0.0101
9 END PGM T MM
