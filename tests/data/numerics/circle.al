% circle.al -- CODE NONLINEAR: where the circle X^2+Y^2 = R^2 meets the line Y = S*X.
VARIABLES X, Y
CONSTANTS R, S
EQ[1] = X^2 + Y^2 - R^2
EQ[2] = Y - S*X
INPUT R = 2, S = 0.5, X = 1, Y = 1
INPUT ABSERR = 1.0E-10, RELERR = 1.0E-10
OUTPUT X, Y
CODE NONLINEAR(EQ, X, Y) circle.c
