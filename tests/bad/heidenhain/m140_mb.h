; expect: 3:8: 'MB50' in an M block is not supported (M140 MB retracts by a distance, M120 looks ahead: the machine would do something else; kin5 reads M140 MB MAX)
0 BEGIN PGM T MM
1 M140 MB 50
2 END PGM T MM
