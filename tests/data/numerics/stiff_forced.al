% stiff_forced.al -- X follows cos(T) through a very fast relaxation
% (X' = -LAMBDA*(X - COS(T)) - SIN(T), exact solution X = COS(T) from X = 1):
% an explicit method must take steps of about 6/LAMBDA, an implicit one need not.
VARIABLES X'
CONSTANTS LAMBDA
X' = -LAMBDA*(X - COS(T)) - SIN(T)
INPUT LAMBDA = 1.0E+06, X = 1
INPUT TFINAL = 2, INTEGSTP = 0.1, ABSERR = 1.0E-08, RELERR = 1.0E-08
OUTPUT T, X
CODE DYNAMICS() stiff_forced.c
