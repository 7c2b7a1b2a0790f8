; expect: 2:15: inch programs are not supported
0 BEGIN PGM T INCH
1 M128
2 L X+0 Y+0 Z+0 B+0 C+0 F100
3 END PGM T MM
