; expect: 4:3: TRANS DATUM changes the working frame; kin5 does not model frame changes
0 BEGIN PGM T MM
1 M128
2 TRANS DATUM AXIS X+10
9 END PGM T MM
