% linear.al -- CODE ALGEBRAIC: two linear equations, one input swept in degrees.
VARIABLES X, Y
CONSTANTS A, B, C
EQ[1] = A*X + 2*Y - SIN(C)
EQ[2] = X - B*Y - 1
INPUT A = 3, B = 0.5, C = 30 DEG
OUTPUT C DEG, X, Y
CODE ALGEBRAIC(EQ, X, Y) [C DEG = 0, 90, 30] linear.c
