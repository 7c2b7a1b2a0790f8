; expect: 3:3: call of LBL 1: no such label in this file
0 BEGIN PGM T MM
1 CALL LBL 1 REP 3
2 END PGM T MM
