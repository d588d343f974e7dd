% whipple_benchmark.al -- the Whipple bicycle of the Meijaard et al. (2007) benchmark, written
% from the benchmark's description.  N3> points down; the rear wheel D touches the
% ground at DN, the front wheel F at FN.  Q1, Q2: rear contact; Q3 yaw; Q4 roll;
% Q5 pitch of the rear frame C, whose C3> is the steer axis (Q5 = LAM upright);
% Q6 rear wheel angle; Q7 steer; Q8 front wheel angle.
NEWTONIAN N
FRAMES    A, B
BODIES    C, D, E, F
POINTS    DN, FN
MOTIONVARIABLES' Q{8}', U{8}'
CONSTANTS W, CT, LAM, G, RR, RF
CONSTANTS MR, IRXX, IRYY, MB, XB, ZB, IBXX, IBYY, IBZZ, IBXZ
CONSTANTS MH, XH, ZH, IHXX, IHYY, IHZZ, IHXZ, MF, IFXX, IFYY

% the steer axis and the wheel centres: D1, D3 perpendicular to the axis, D2 along it
D1 = COS(LAM)*(W + CT - RR*TAN(LAM))
D3 = -COS(LAM)*(CT - RF*TAN(LAM))
D2 = (RR + D1*SIN(LAM) - RF + D3*SIN(LAM))/COS(LAM)
% the mass centres of the rear frame (from DO) and the front frame (from FO)
L1 = XB*COS(LAM) - (ZB + RR)*SIN(LAM)
L2 = XB*SIN(LAM) + (ZB + RR)*COS(LAM)
L3 = (XH - W)*COS(LAM) - (ZH + RF)*SIN(LAM)
L4 = (XH - W)*SIN(LAM) + (ZH + RF)*COS(LAM)

SIMPROT(N, A, 3, Q3)
SIMPROT(A, B, 1, Q4)
SIMPROT(B, C, 2, Q5)
SIMPROT(C, D, 2, Q6)
SIMPROT(C, E, 3, Q7)
SIMPROT(E, F, 2, Q8)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
Q6' = U6
Q7' = U7
Q8' = U8

MASS C = MB, D = MR, E = MH, F = MF
% the benchmark's inertias (in N's axes upright) turned by LAM into C's and E's axes
INERTIA C, COS(LAM)^2*IBXX - 2*SIN(LAM)*COS(LAM)*IBXZ + SIN(LAM)^2*IBZZ, IBYY, &
  SIN(LAM)^2*IBXX + 2*SIN(LAM)*COS(LAM)*IBXZ + COS(LAM)^2*IBZZ, 0, 0, &
  SIN(LAM)*COS(LAM)*(IBXX - IBZZ) + (COS(LAM)^2 - SIN(LAM)^2)*IBXZ
INERTIA E, COS(LAM)^2*IHXX - 2*SIN(LAM)*COS(LAM)*IHXZ + SIN(LAM)^2*IHZZ, IHYY, &
  SIN(LAM)^2*IHXX + 2*SIN(LAM)*COS(LAM)*IHXZ + COS(LAM)^2*IHZZ, 0, 0, &
  SIN(LAM)*COS(LAM)*(IHXX - IHZZ) + (COS(LAM)^2 - SIN(LAM)^2)*IHXZ
INERTIA D, IRXX, IRYY, IRXX
INERTIA F, IFXX, IFYY, IFXX

P_NO_DN> = Q1*N1> + Q2*N2>
P_DN_DO> = -RR*B3>
P_DO_CO> = L1*C1> + L2*C3>
P_DO_FO> = D1*C1> + D2*C3> + D3*E1>
P_FO_EO> = L3*E1> + L4*E3>
P_FO_FN> = RF*UNITVEC(N3> - DOT(N3>, E2>)*E2>)

V_DO_N> = DT(P_NO_DO>, N)
V_CO_N> = DT(P_NO_CO>, N)
V_FO_N> = DT(P_NO_FO>, N)
V_EO_N> = DT(P_NO_EO>, N)
V2PTS(N, D, DO, DN)
V2PTS(N, F, FO, FN)

% rolling without slip; the vertical velocity of FN keeps the front wheel on the ground
DEPENDENT[1] = DOT(V_DN_N>, N1>)
DEPENDENT[2] = DOT(V_DN_N>, N2>)
DEPENDENT[3] = DOT(V_FN_N>, N1>)
DEPENDENT[4] = DOT(V_FN_N>, N2>)
DEPENDENT[5] = DOT(V_FN_N>, N3>)
CONSTRAIN(DEPENDENT[U1, U2, U3, U5, U8])

GRAVITY(G*N3>)
ZERO = FR() + FRSTAR()
KANE()

INPUT W = 1.02, CT = 0.08, LAM = 0.3141592653589793, G = 9.81
INPUT RR = 0.3, MR = 2, IRXX = 0.0603, IRYY = 0.12
INPUT XB = 0.3, ZB = -0.9, MB = 85, IBXX = 9.2, IBYY = 11, IBZZ = 2.8, IBXZ = 2.4
INPUT XH = 0.9, ZH = -0.7, MH = 4, IHXX = 0.05892, IHYY = 0.06, IHZZ = 0.00708, IHXZ = -0.00756
INPUT RF = 0.35, MF = 3, IFXX = 0.1405, IFYY = 0.28
% upright (pitch = LAM, in radians), rolling at 5 m/s
INPUT Q5 = 0.3141592653589793 RAD, U6 = -16.666666666666668 RAD/SEC
INPUT TFINAL = 1
OUTPUT Q4, Q7
CODE DYNAMICS() whipple_benchmark.c
