; expect: 3:21: word 'I' needs G2, G3 or G43.5
G43.4 H1
G1 X0 Y0 Z0 A10. C0 I1. F100
