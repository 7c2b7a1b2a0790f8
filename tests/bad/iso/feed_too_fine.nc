; expect: 3:21: the feed 0.0004 cannot be written with 3 decimals, the most the controller reads (it would read as 0)
G43.4 H1
G1 X0 Y0 Z0 A10. C0 F.0004
