% rolling_disc.al -- a thin disc rolling without slip on the horizontal plane of
% N (N3> up).  Q1 yaw, Q2 lean, Q3 spin; Q4, Q5 locate the contact point.  The
% no-slip conditions make U4 and U5 dependent speeds.

NEWTONIAN N
FRAMES    A, B                 % yaw frame, lean frame
BODIES    C                    % the disc; C2> is its axis
POINTS    CN                   % the disc's point in contact with the ground
MOTIONVARIABLES' Q{5}', U{5}'
CONSTANTS R, M, G

MASS C = M
INERTIA C, M*R^2/4, M*R^2/2, M*R^2/4

SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
SIMPROT(B, C, 2, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5

P_NO_CO> = Q4*N1> + Q5*N2> + R*B3>
V_CO_N> = DT(P_NO_CO>, N)
P_CO_CN> = -R*B3>
V2PTS(N, C, CO, CN)

% rolling without slip: the contact point of the disc is at rest
DEPENDENT[1] = DOT(V_CN_N>, N1>)
DEPENDENT[2] = DOT(V_CN_N>, N2>)
CONSTRAIN(DEPENDENT[U4, U5])

GRAVITY(-G*N3>)
ZERO = FR() + FRSTAR()
KANE()

INPUT R = 0.3 m, M = 2 kg, G = 9.81 m/sec^2
INPUT Q1 = 0, Q2 = 5 deg, Q3 = 0, Q4 = 0, Q5 = 0
INPUT U1 = 0, U2 = 0, U3 = 8 rad/sec
INPUT TFINAL = 3, INTEGSTP = 0.01
OUTPUT T sec, Q1 deg, Q2 deg, Q4 m, Q5 m
CODE DYNAMICS() rolling_disc.c
