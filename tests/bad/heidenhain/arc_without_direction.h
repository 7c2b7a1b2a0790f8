; expect: 6:3: arc needs a direction (DR+ or DR-)
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 CC X+5 Y+0
4 C X+10 Y+0
9 END PGM T MM
