; expect: 2:1: call of O1000: no such label in this file
N20 M98 P1000
M30
