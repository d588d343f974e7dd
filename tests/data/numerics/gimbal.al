% gimbal.al -- a free rigid body oriented by body-fixed 1-2-3 angles whose rates are
% the generalized speeds: the mass matrix is singular where Q2 = 90 deg (gimbal lock).
NEWTONIAN N
FRAMES A, C
BODIES B
MOTIONVARIABLES' Q{3}''
CONSTANTS M, I1, I2, I3
MASS B = M
INERTIA B, I1, I2, I3
SIMPROT(N, A, 1, Q1)
SIMPROT(A, C, 2, Q2)
SIMPROT(C, B, 3, Q3)
V_BO_N> = 0>
ZERO = FR() + FRSTAR()
KANE()
INPUT M = 1, I1 = 1, I2 = 2, I3 = 3
INPUT Q1 = 10 deg, Q2 = 60 deg, Q3 = 20 deg, Q1' = 0.2, Q2' = 0.1, Q3' = 0.3
INPUT TFINAL = 1, INTEGSTP = 0.1
OUTPUT T, Q1, Q2, Q3
CODE DYNAMICS() gimbal.c
