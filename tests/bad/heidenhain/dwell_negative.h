; expect: 4:22: CYCL DEF 9.1 DWELL: a dwell time cannot be negative
0 BEGIN PGM T MM
1 CYCL DEF 9.0 DWELL TIME
2 CYCL DEF 9.1 DWELL -2
3 END PGM T MM
