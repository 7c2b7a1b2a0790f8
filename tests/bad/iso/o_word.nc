; expect: 3:1: o-word control flow is not supported
G43.4 H1
o100 if [1]
