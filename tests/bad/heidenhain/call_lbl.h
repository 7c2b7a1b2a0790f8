; expect: 3:3: CALL LBL: program and label calls are not supported (the motion they make would be lost)
0 BEGIN PGM T MM
1 CALL LBL 1 REP 3
2 END PGM T MM
