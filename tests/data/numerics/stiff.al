% stiff.al -- X' = -LAMBDA*X with a huge LAMBDA: Autolev's Kutta-Merson halves its
% step too many times and stops, keeping the rows written so far.
VARIABLES X'
CONSTANTS LAMBDA
X' = -LAMBDA*X
INPUT LAMBDA = 1.0E+09, X = 1
INPUT TFINAL = 1, INTEGSTP = 0.1
OUTPUT T, X
CODE DYNAMICS() stiff.c
