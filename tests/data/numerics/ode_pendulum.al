% ode_pendulum.al -- CODE ODE: a pendulum written as an equation solved for THETA''.
VARIABLES THETA''
CONSTANTS G, L
EQ = L*THETA'' + G*SIN(THETA)
INPUT G = 9.81, L = 1, THETA = 10 DEG, THETA' = 0
INPUT TFINAL = 2, INTEGSTP = 0.01
OUTPUT T, THETA DEG
CODE ODE(EQ, THETA'') ode_pendulum.c
