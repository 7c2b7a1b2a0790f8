; expect: 3:1: expressions and parameters are not supported
G43.4 H1
#1=5
