; expect: 3:3: CYCL DEF 9.0 (dwell time) without its CYCL DEF 9.1 DWELL block after it
0 BEGIN PGM T MM
1 CYCL DEF 9.0 DWELL TIME
2 END PGM T MM
