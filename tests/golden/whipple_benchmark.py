"""Translated from whipple_benchmark.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import sympy as sm

import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('whipple_benchmark')
t = model.t

# whipple_benchmark.al -- the Whipple bicycle of the Meijaard et al. (2007) benchmark, written
# from the benchmark's description.  N3> points down; the rear wheel D touches the
# ground at DN, the front wheel F at FN.  Q1, Q2: rear contact; Q3 yaw; Q4 roll;
# Q5 pitch of the rear frame C, whose C3> is the steer axis (Q5 = LAM upright);
# Q6 rear wheel angle; Q7 steer; Q8 front wheel angle.
# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# FRAMES    A, B
A, B = model.frames('A B')
# BODIES    C, D, E, F
C, D, E, F = model.bodies('C D E F')
CO = C.masscenter
DO = D.masscenter
EO = E.masscenter
FO = F.masscenter
# POINTS    DN, FN
DN, FN = model.points('DN FN')
# MOTIONVARIABLES' Q{8}', U{8}'
Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8, U1, U2, U3, U4, U5, U6, U7, U8 = model.motion_variables('Q1 Q2 Q3 Q4 Q5 Q6 Q7 Q8 U1 U2 U3 U4 U5 U6 U7 U8', order=1)
Q1p, Q2p, Q3p, Q4p, Q5p, Q6p, Q7p, Q8p = al.derivatives(Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8)
# CONSTANTS W, CT, LAM, G, RR, RF
W, CT, LAM, G, RR, RF = model.constants('W CT LAM G RR RF')
# CONSTANTS MR, IRXX, IRYY, MB, XB, ZB, IBXX, IBYY, IBZZ, IBXZ
MR, IRXX, IRYY, MB, XB, ZB, IBXX, IBYY, IBZZ, IBXZ = model.constants('MR IRXX IRYY MB XB ZB IBXX IBYY IBZZ IBXZ')
# CONSTANTS MH, XH, ZH, IHXX, IHYY, IHZZ, IHXZ, MF, IFXX, IFYY
MH, XH, ZH, IHXX, IHYY, IHZZ, IHXZ, MF, IFXX, IFYY = model.constants('MH XH ZH IHXX IHYY IHZZ IHXZ MF IFXX IFYY')

# the steer axis and the wheel centres: D1, D3 perpendicular to the axis, D2 along it
# D1 = COS(LAM)*(W + CT - RR*TAN(LAM))
D1 = sm.cos(LAM)*(W + CT - RR*sm.tan(LAM))
# D3 = -COS(LAM)*(CT - RF*TAN(LAM))
D3 = -sm.cos(LAM)*(CT - RF*sm.tan(LAM))
# D2 = (RR + D1*SIN(LAM) - RF + D3*SIN(LAM))/COS(LAM)
D2 = (RR + D1*sm.sin(LAM) - RF + D3*sm.sin(LAM))/sm.cos(LAM)
# the mass centres of the rear frame (from DO) and the front frame (from FO)
# L1 = XB*COS(LAM) - (ZB + RR)*SIN(LAM)
L1 = XB*sm.cos(LAM) - (ZB + RR)*sm.sin(LAM)
# L2 = XB*SIN(LAM) + (ZB + RR)*COS(LAM)
L2 = XB*sm.sin(LAM) + (ZB + RR)*sm.cos(LAM)
# L3 = (XH - W)*COS(LAM) - (ZH + RF)*SIN(LAM)
L3 = (XH - W)*sm.cos(LAM) - (ZH + RF)*sm.sin(LAM)
# L4 = (XH - W)*SIN(LAM) + (ZH + RF)*COS(LAM)
L4 = (XH - W)*sm.sin(LAM) + (ZH + RF)*sm.cos(LAM)

# SIMPROT(N, A, 3, Q3)
A.orient_axis(N, N.z, Q3)
# SIMPROT(A, B, 1, Q4)
B.orient_axis(A, A.x, Q4)
# SIMPROT(B, C, 2, Q5)
C.orient_axis(B, B.y, Q5)
# SIMPROT(C, D, 2, Q6)
D.orient_axis(C, C.y, Q6)
# SIMPROT(C, E, 3, Q7)
E.orient_axis(C, C.z, Q7)
# SIMPROT(E, F, 2, Q8)
F.orient_axis(E, E.y, Q8)
# Q1' = U1
model.define(Q1p, U1)
# Q2' = U2
model.define(Q2p, U2)
# Q3' = U3
model.define(Q3p, U3)
# Q4' = U4
model.define(Q4p, U4)
# Q5' = U5
model.define(Q5p, U5)
# Q6' = U6
model.define(Q6p, U6)
# Q7' = U7
model.define(Q7p, U7)
# Q8' = U8
model.define(Q8p, U8)

# MASS C = MB, D = MR, E = MH, F = MF
C.mass = MB
D.mass = MR
E.mass = MH
F.mass = MF
# the benchmark's inertias (in N's axes upright) turned by LAM into C's and E's axes
# INERTIA C, COS(LAM)^2*IBXX - 2*SIN(LAM)*COS(LAM)*IBXZ + SIN(LAM)^2*IBZZ, IBYY, &
#   SIN(LAM)^2*IBXX + 2*SIN(LAM)*COS(LAM)*IBXZ + COS(LAM)^2*IBZZ, 0, 0, &
#   SIN(LAM)*COS(LAM)*(IBXX - IBZZ) + (COS(LAM)^2 - SIN(LAM)^2)*IBXZ
C.set_inertia(sm.cos(LAM)**2*IBXX - 2*sm.sin(LAM)*sm.cos(LAM)*IBXZ + sm.sin(LAM)**2*IBZZ, IBYY, sm.sin(LAM)**2*IBXX + 2*sm.sin(LAM)*sm.cos(LAM)*IBXZ + sm.cos(LAM)**2*IBZZ, 0, 0, sm.sin(LAM)*sm.cos(LAM)*(IBXX - IBZZ) + (sm.cos(LAM)**2 - sm.sin(LAM)**2)*IBXZ)
# INERTIA E, COS(LAM)^2*IHXX - 2*SIN(LAM)*COS(LAM)*IHXZ + SIN(LAM)^2*IHZZ, IHYY, &
#   SIN(LAM)^2*IHXX + 2*SIN(LAM)*COS(LAM)*IHXZ + COS(LAM)^2*IHZZ, 0, 0, &
#   SIN(LAM)*COS(LAM)*(IHXX - IHZZ) + (COS(LAM)^2 - SIN(LAM)^2)*IHXZ
E.set_inertia(sm.cos(LAM)**2*IHXX - 2*sm.sin(LAM)*sm.cos(LAM)*IHXZ + sm.sin(LAM)**2*IHZZ, IHYY, sm.sin(LAM)**2*IHXX + 2*sm.sin(LAM)*sm.cos(LAM)*IHXZ + sm.cos(LAM)**2*IHZZ, 0, 0, sm.sin(LAM)*sm.cos(LAM)*(IHXX - IHZZ) + (sm.cos(LAM)**2 - sm.sin(LAM)**2)*IHXZ)
# INERTIA D, IRXX, IRYY, IRXX
D.set_inertia(IRXX, IRYY, IRXX)
# INERTIA F, IFXX, IFYY, IFXX
F.set_inertia(IFXX, IFYY, IFXX)

# P_NO_DN> = Q1*N1> + Q2*N2>
DN.set_pos(NO, Q1*N.x + Q2*N.y)
# P_DN_DO> = -RR*B3>
DO.set_pos(DN, -RR*B.z)
# P_DO_CO> = L1*C1> + L2*C3>
CO.set_pos(DO, L1*C.x + L2*C.z)
# P_DO_FO> = D1*C1> + D2*C3> + D3*E1>
FO.set_pos(DO, D1*C.x + D2*C.z + D3*E.x)
# P_FO_EO> = L3*E1> + L4*E3>
EO.set_pos(FO, L3*E.x + L4*E.z)
# P_FO_FN> = RF*UNITVEC(N3> - DOT(N3>, E2>)*E2>)
FN.set_pos(FO, RF*al.unitvec(N.z - al.dot(N.z, E.y)*E.y))

# V_DO_N> = DT(P_NO_DO>, N)
DO.set_vel(N, model.dt(DO.pos_from(NO), N))
# V_CO_N> = DT(P_NO_CO>, N)
CO.set_vel(N, model.dt(CO.pos_from(NO), N))
# V_FO_N> = DT(P_NO_FO>, N)
FO.set_vel(N, model.dt(FO.pos_from(NO), N))
# V_EO_N> = DT(P_NO_EO>, N)
EO.set_vel(N, model.dt(EO.pos_from(NO), N))
# V2PTS(N, D, DO, DN)
DN.v2pt_theory(DO, N, D)
# V2PTS(N, F, FO, FN)
FN.v2pt_theory(FO, N, F)

# rolling without slip; the vertical velocity of FN keeps the front wheel on the ground
# DEPENDENT[1] = DOT(V_DN_N>, N1>)
# DEPENDENT[2] = DOT(V_DN_N>, N2>)
# DEPENDENT[3] = DOT(V_FN_N>, N1>)
# DEPENDENT[4] = DOT(V_FN_N>, N2>)
# DEPENDENT[5] = DOT(V_FN_N>, N3>)
DEPENDENT = sm.Matrix([
    al.dot(DN.vel(N), N.x),
    al.dot(DN.vel(N), N.y),
    al.dot(FN.vel(N), N.x),
    al.dot(FN.vel(N), N.y),
    al.dot(FN.vel(N), N.z),
])
# CONSTRAIN(DEPENDENT[U1, U2, U3, U5, U8])
model.constrain(DEPENDENT, [U1, U2, U3, U5, U8])

# GRAVITY(G*N3>)
model.gravity(G*N.z)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT W = 1.02, CT = 0.08, LAM = 0.3141592653589793, G = 9.81
model.input(W, 1.02)
model.input(CT, 0.08)
model.input(LAM, 0.3141592653589793)
model.input(G, 9.81)
# INPUT RR = 0.3, MR = 2, IRXX = 0.0603, IRYY = 0.12
model.input(RR, 0.3)
model.input(MR, 2)
model.input(IRXX, 0.0603)
model.input(IRYY, 0.12)
# INPUT XB = 0.3, ZB = -0.9, MB = 85, IBXX = 9.2, IBYY = 11, IBZZ = 2.8, IBXZ = 2.4
model.input(XB, 0.3)
model.input(ZB, -0.9)
model.input(MB, 85)
model.input(IBXX, 9.2)
model.input(IBYY, 11)
model.input(IBZZ, 2.8)
model.input(IBXZ, 2.4)
# INPUT XH = 0.9, ZH = -0.7, MH = 4, IHXX = 0.05892, IHYY = 0.06, IHZZ = 0.00708, IHXZ = -0.00756
model.input(XH, 0.9)
model.input(ZH, -0.7)
model.input(MH, 4)
model.input(IHXX, 0.05892)
model.input(IHYY, 0.06)
model.input(IHZZ, 0.00708)
model.input(IHXZ, -0.00756)
# INPUT RF = 0.35, MF = 3, IFXX = 0.1405, IFYY = 0.28
model.input(RF, 0.35)
model.input(MF, 3)
model.input(IFXX, 0.1405)
model.input(IFYY, 0.28)
# upright (pitch = LAM, in radians), rolling at 5 m/s
# INPUT Q5 = 0.3141592653589793 RAD, U6 = -16.666666666666668 RAD/SEC
model.input(Q5, 0.3141592653589793, 'RAD')
model.input(U6, -16.666666666666668, 'RAD/SEC')
# INPUT TFINAL = 1
model.input('TFINAL', 1)
# OUTPUT Q4, Q7
model.output((Q4, 'Q4'), (Q7, 'Q7'))
# CODE DYNAMICS() whipple_benchmark.c
model.code('dynamics', 'whipple_benchmark.c', zero=ZERO)
