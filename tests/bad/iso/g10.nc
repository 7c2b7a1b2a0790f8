; expect: 2:1: G10: setting offsets from the program is not supported (later moves would use other offsets)
G10 L2 P1 X0. Y0. Z0.
M30
