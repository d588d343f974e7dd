% forced.al -- a mass on a spring driven by a specified force F, given or defined.
NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' X', V'
CONSTANTS K, M
SPECIFIED F
MASS P = M
X' = V
P_NO_P> = X*N1>
V_P_N> = V*N1>
FORCE_P> = (F - K*X)*N1>
ZERO = FR() + FRSTAR()
KANE()
INPUT K = 1, M = 1, X = 0, V = 0
INPUT TFINAL = 2, INTEGSTP = 0.1
OUTPUT T, X, F
CODE DYNAMICS() forced.c
