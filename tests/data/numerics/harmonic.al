% harmonic.al -- a particle on a linear spring along N1>: X'' = -(K/M)*X.
% Closed form: X = X0*COS(W*T) + V0/W*SIN(W*T), W = SQRT(K/M).
NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' X', V'
CONSTANTS K, M
MASS P = M
X' = V
P_NO_P> = X*N1>
V_P_N> = V*N1>
FORCE_P> = -K*X*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT K = 4, M = 1, X = 0.2, V = 0.3
INPUT TFINAL = 3, INTEGSTP = 0.05, PRINTINT = 2
OUTPUT T, X, V, V'
CODE DYNAMICS() harmonic.c
