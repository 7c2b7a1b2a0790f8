; expect: 5:3: CYCL DEF 7 changes the working frame; kin5 does not model frame changes
0 BEGIN PGM T MM
1 M128
2 CYCL DEF 7.0 DATUM SHIFT
3 CYCL DEF 7.1 X+10
9 END PGM T MM
