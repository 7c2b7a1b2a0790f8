; expect: 3:5: incremental X (G91 of line 3) from a position the program does not say: no absolute X since the start of the program, so the move would start from wherever the machine stands; program an absolute X (G90) before it
G43.4 H1
G91 X1.
