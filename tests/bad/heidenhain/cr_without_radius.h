; expect: 5:3: CR needs a radius (R)
0 BEGIN PGM T MM
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 CR X+10 Y+0 DR+
9 END PGM T MM
