; expect: 4:3: PLANE SPATIAL changes the working frame; kin5 does not model frame changes
0 BEGIN PGM T MM
1 M128
2 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN
9 END PGM T MM
