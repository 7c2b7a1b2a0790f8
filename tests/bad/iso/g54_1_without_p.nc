; expect: 2:1: G54.1 needs P n, the number of the extended work offset
G54.1
G43.4 H1
G1 X0. Y0. Z0. A10. C0. F100.
