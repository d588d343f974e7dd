% euler_parameters_body.al -- a rigid body turning about its fixed mass center
% under a constant torque.  Its orientation in N is given by Euler parameters
% (E4 the scalar part); the speeds are its angular velocity measure numbers in B.

NEWTONIAN N
BODIES    B
VARIABLES E{4}'
MOTIONVARIABLES' U{3}'
CONSTANTS M, I1, I2, I3, T1, T2, T3

MASS B = M
INERTIA B, I1, I2, I3

DIRCOS(N, B, EULER, E1, E2, E3, E4)
W_B_N> = U1*B1> + U2*B2> + U3*B3>
KINDIFFS(N, B, EULER, E1, E2, E3, E4)

P_NO_BO> = 0>
V_BO_N> = 0>

TORQUE(B, T1*B1> + T2*B2> + T3*B3>)
ZERO = FR() + FRSTAR()
KANE()

INPUT M = 1, I1 = 0.2, I2 = 0.3, I3 = 0.45, T1 = 0, T2 = 0.01, T3 = 0
INPUT E1 = 0, E2 = 0, E3 = 0, E4 = 1
INPUT U1 = 0.1, U2 = 2, U3 = 0.05
INPUT TFINAL = 10, INTEGSTP = 0.05
OUTPUT T, E1, E2, E3, E4, U1, U2, U3
CODE DYNAMICS() euler_parameters_body.c
