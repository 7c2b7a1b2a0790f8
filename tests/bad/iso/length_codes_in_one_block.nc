; expect: 3:11: G43.4 and G49 in one block: two tool length codes of one modal group (08), which cannot both apply; write the one meant
T40 M6
G43.4 H40 G49
G1 X0. Y0. Z10. A0. C0. F100.
