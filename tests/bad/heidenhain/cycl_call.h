; expect: 3:3: CYCL CALL: a cycle call is not supported (fixed cycles are refused until kin5 reads them)
0 BEGIN PGM T MM
1 CYCL CALL
2 END PGM T MM
