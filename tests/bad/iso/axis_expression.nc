; expect: 3:7: the value of word 'X' goes on after its end (an expression in a word is bracketed: X[…])
G43.4 H1
G1 X#1+2 Y0 Z0 A10. C0 F100
