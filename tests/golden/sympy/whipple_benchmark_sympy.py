"""whipple_benchmark: the model in sympy.physics.mechanics, written by autolev from
whipple_benchmark.al (CODE DYNAMICS whipple_benchmark.c).

Level: mechanics.  Frames, points, particles and rigid bodies, loads and the
kinematical differential equations as the model gives them; sympy's KanesMethod
forms the equations of motion when the script is imported.  Importing defines
`kane` (its equations formed), `constants`, `initial_conditions` and `specified`;
`python THIS.py [OUT.csv]` integrates from TINITIAL to TFINAL with scipy
(DOP853, RELERR and ABSERR) and writes the OUTPUT columns as CSV.
"""
import sys

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

t = me.dynamicsymbols._t

# generalized coordinates and speeds: functions of time
Q1 = me.dynamicsymbols('Q1')
Q2 = me.dynamicsymbols('Q2')
Q3 = me.dynamicsymbols('Q3')
Q4 = me.dynamicsymbols('Q4')
Q5 = me.dynamicsymbols('Q5')
Q6 = me.dynamicsymbols('Q6')
Q7 = me.dynamicsymbols('Q7')
Q8 = me.dynamicsymbols('Q8')
U4 = me.dynamicsymbols('U4')
U6 = me.dynamicsymbols('U6')
U7 = me.dynamicsymbols('U7')
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')
U5 = me.dynamicsymbols('U5')
U8 = me.dynamicsymbols('U8')

# constants
W = sm.Symbol('W')
CT = sm.Symbol('CT')
LAM = sm.Symbol('LAM')
G = sm.Symbol('G')
RR = sm.Symbol('RR')
RF = sm.Symbol('RF')
MR = sm.Symbol('MR')
IRXX = sm.Symbol('IRXX')
IRYY = sm.Symbol('IRYY')
MB = sm.Symbol('MB')
XB = sm.Symbol('XB')
ZB = sm.Symbol('ZB')
IBXX = sm.Symbol('IBXX')
IBYY = sm.Symbol('IBYY')
IBZZ = sm.Symbol('IBZZ')
IBXZ = sm.Symbol('IBXZ')
MH = sm.Symbol('MH')
XH = sm.Symbol('XH')
ZH = sm.Symbol('ZH')
IHXX = sm.Symbol('IHXX')
IHYY = sm.Symbol('IHYY')
IHZZ = sm.Symbol('IHZZ')
IHXZ = sm.Symbol('IHXZ')
MF = sm.Symbol('MF')
IFXX = sm.Symbol('IFXX')
IFYY = sm.Symbol('IFYY')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# whipple_benchmark.al:25: SIMPROT(N, A, 3, Q3)
A = me.ReferenceFrame('A')
A.orient_axis(N, N.z, Q3)
A.set_ang_vel(N, U3*N.z)
# whipple_benchmark.al:26: SIMPROT(A, B, 1, Q4)
B = me.ReferenceFrame('B')
B.orient_axis(A, A.x, Q4)
B.set_ang_vel(A, U4*A.x)
# whipple_benchmark.al:27: SIMPROT(B, C, 2, Q5)
C = me.ReferenceFrame('C')
C.orient_axis(B, B.y, Q5)
C.set_ang_vel(B, U5*B.y)
# whipple_benchmark.al:28: SIMPROT(C, D, 2, Q6)
D = me.ReferenceFrame('D')
D.orient_axis(C, C.y, Q6)
D.set_ang_vel(C, U6*C.y)
# whipple_benchmark.al:29: SIMPROT(C, E, 3, Q7)
E = me.ReferenceFrame('E')
E.orient_axis(C, C.z, Q7)
E.set_ang_vel(C, U7*C.z)
# whipple_benchmark.al:30: SIMPROT(E, F, 2, Q8)
F = me.ReferenceFrame('F')
F.orient_axis(E, E.y, Q8)
F.set_ang_vel(E, U8*E.y)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
CO = me.Point('CO')
DO = me.Point('DO')
EO = me.Point('EO')
FO = me.Point('FO')
DN = me.Point('DN')
NO = me.Point('NO')
FN = me.Point('FN')
# whipple_benchmark.al:51: P_NO_DN> = Q1*N1> + Q2*N2>
DN.set_pos(NO, Q1*N.x + Q2*N.y)
# whipple_benchmark.al:52: P_DN_DO> = -RR*B3>
DO.set_pos(DN, (-RR)*B.z)
# whipple_benchmark.al:53: P_DO_CO> = L1*C1> + L2*C3>
CO.set_pos(DO, (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*C.x + (XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*C.z)
# whipple_benchmark.al:54: P_DO_FO> = D1*C1> + D2*C3> + D3*E1>
FO.set_pos(DO, (CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*C.x + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM)*C.z + (-(CT - RF*sm.tan(LAM))*sm.cos(LAM))*E.x)
# whipple_benchmark.al:55: P_FO_EO> = L3*E1> + L4*E3>
EO.set_pos(FO, (-(RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*E.x + ((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*E.z)
# whipple_benchmark.al:56: P_FO_FN> = RF*UNITVEC(N3> - DOT(N3>, E2>)*E2>)
FN.set_pos(FO, RF/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2))*N.z + (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)))*E.y)
# whipple_benchmark.al:59: V_CO_N> = DT(P_NO_CO>, N)
CO.set_vel(N, (-RR*U3*sm.sin(Q4)*sm.cos(Q3) - ((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*(sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5)) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*(sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3)))*U3 + U1)*N.x + (-RR*U3*sm.sin(Q3)*sm.sin(Q4) + ((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*(sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3)) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*(-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5)))*U3 + U2)*N.y + (RR*U4*sm.cos(Q4) - ((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5)*sm.cos(Q4))*U4)*A.y + (RR*U4*sm.sin(Q4) + (-(XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q4)*sm.sin(Q5))*U4)*A.z + ((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.cos(Q5) - (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.sin(Q5))*U5*B.x + (-((XB*sm.sin(LAM) + (RR + ZB)*sm.cos(LAM))*sm.sin(Q5) + (XB*sm.cos(LAM) - (RR + ZB)*sm.sin(LAM))*sm.cos(Q5))*U5)*B.z)
# whipple_benchmark.al:58: V_DO_N> = DT(P_NO_DO>, N)
DO.set_vel(N, (-RR*U3*sm.sin(Q4)*sm.cos(Q3) + U1)*N.x + (-RR*U3*sm.sin(Q3)*sm.sin(Q4) + U2)*N.y + RR*U4*sm.cos(Q4)*A.y + RR*U4*sm.sin(Q4)*A.z)
# whipple_benchmark.al:61: V_EO_N> = DT(P_NO_EO>, N)
EO.set_vel(N, (-RR*U3*sm.sin(Q4)*sm.cos(Q3) - (((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*(sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5)) + ((sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7))*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))*U3 - ((sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) + (sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))*U3 + U1)*N.x + (-RR*U3*sm.sin(Q3)*sm.sin(Q4) + (((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*(sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3)) + (-(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7))*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))*U3 + ((-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + (sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))*U3 + U2)*N.y + (RR*U4*sm.cos(Q4) - (((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q4)*sm.cos(Q5) + (sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))*U4 - (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*A.y + (RR*U4*sm.sin(Q4) + (-((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q4)*sm.cos(Q5) + (sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM)))*U4 + ((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*A.z + ((((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.cos(Q5) - (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q7))*U5 + (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))*U5)*B.x + (-(((RF + ZH)*sm.cos(LAM) + (-W + XH)*sm.sin(LAM))*sm.sin(Q5) + (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*sm.cos(Q5)*sm.cos(Q7))*U5 - ((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))*U5)*B.z + (-(-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*U7*sm.sin(Q7))*C.x + (-(CT - RF*sm.tan(LAM))*sm.cos(LAM) - (RF + ZH)*sm.sin(LAM) + (-W + XH)*sm.cos(LAM))*U7*sm.cos(Q7)*C.y)
# whipple_benchmark.al:60: V_FO_N> = DT(P_NO_FO>, N)
FO.set_vel(N, (-RR*U3*sm.sin(Q4)*sm.cos(Q3) + (CT - RF*sm.tan(LAM))*((sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7))*U3*sm.cos(LAM) - ((sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) + (sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))*U3 + U1)*N.x + (-RR*U3*sm.sin(Q3)*sm.sin(Q4) - (CT - RF*sm.tan(LAM))*(-(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7))*U3*sm.cos(LAM) + ((-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + (sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))*U3 + U2)*N.y + (RR*U4*sm.cos(Q4) + (CT - RF*sm.tan(LAM))*(sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*U4*sm.cos(LAM) - (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*A.y + (RR*U4*sm.sin(Q4) - (CT - RF*sm.tan(LAM))*(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*U4*sm.cos(LAM) + ((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*A.z + ((CT - RF*sm.tan(LAM))*U5*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7) + (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))*U5)*B.x + ((CT - RF*sm.tan(LAM))*U5*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - ((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))*U5)*B.z + (CT - RF*sm.tan(LAM))*U7*sm.sin(Q7)*sm.cos(LAM)*C.x + (-(CT - RF*sm.tan(LAM))*U7*sm.cos(LAM)*sm.cos(Q7))*C.y)

# particles and rigid bodies: masses and central inertias
# whipple_benchmark.al:40: MASS C = MB, D = MR, E = MH, F = MF
# whipple_benchmark.al:42: INERTIA C, COS(LAM)^2*IBXX - 2*SIN(LAM)*COS(LAM)*IBXZ + SIN(LAM)^2*...
C_body = me.RigidBody('C', CO, C, MB, (me.inertia(C, IBXX*sm.cos(LAM)**2 - 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.sin(LAM)**2, IBYY, IBXX*sm.sin(LAM)**2 + 2*IBXZ*sm.sin(LAM)*sm.cos(LAM) + IBZZ*sm.cos(LAM)**2, 0, 0, IBXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IBXX - IBZZ)*sm.sin(LAM)*sm.cos(LAM)), CO))
# whipple_benchmark.al:40: MASS C = MB, D = MR, E = MH, F = MF
# whipple_benchmark.al:48: INERTIA D, IRXX, IRYY, IRXX
D_body = me.RigidBody('D', DO, D, MR, (me.inertia(D, IRXX, IRYY, IRXX), DO))
# whipple_benchmark.al:40: MASS C = MB, D = MR, E = MH, F = MF
# whipple_benchmark.al:45: INERTIA E, COS(LAM)^2*IHXX - 2*SIN(LAM)*COS(LAM)*IHXZ + SIN(LAM)^2*...
E_body = me.RigidBody('E', EO, E, MH, (me.inertia(E, IHXX*sm.cos(LAM)**2 - 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.sin(LAM)**2, IHYY, IHXX*sm.sin(LAM)**2 + 2*IHXZ*sm.sin(LAM)*sm.cos(LAM) + IHZZ*sm.cos(LAM)**2, 0, 0, IHXZ*(-sm.sin(LAM)**2 + sm.cos(LAM)**2) + (IHXX - IHZZ)*sm.sin(LAM)*sm.cos(LAM)), EO))
# whipple_benchmark.al:40: MASS C = MB, D = MR, E = MH, F = MF
# whipple_benchmark.al:49: INERTIA F, IFXX, IFYY, IFXX
F_body = me.RigidBody('F', FO, F, MF, (me.inertia(F, IFXX, IFYY, IFXX), FO))
bodies = [C_body, D_body, E_body, F_body]

# loads: forces on points, torques on frames
# whipple_benchmark.al:73: GRAVITY(G*N3>)
loads = [
    (CO, G*MB*N.z),
    (DO, G*MR*N.z),
    (EO, G*MH*N.z),
    (FO, G*MF*N.z),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # whipple_benchmark.al:31: Q1' = U1
    Q1.diff(t) - U1,
    # whipple_benchmark.al:32: Q2' = U2
    Q2.diff(t) - U2,
    # whipple_benchmark.al:33: Q3' = U3
    Q3.diff(t) - U3,
    # whipple_benchmark.al:34: Q4' = U4
    Q4.diff(t) - U4,
    # whipple_benchmark.al:35: Q5' = U5
    Q5.diff(t) - U5,
    # whipple_benchmark.al:36: Q6' = U6
    Q6.diff(t) - U6,
    # whipple_benchmark.al:37: Q7' = U7
    Q7.diff(t) - U7,
    # whipple_benchmark.al:38: Q8' = U8
    Q8.diff(t) - U8,
]

# velocity constraints (each = 0), which give the dependent speeds (CONSTRAIN(DEPENDENT[...]));
# KanesMethod solves them by Cramer's rule: its default LU divides by pivots that
# vanish at some states where the constraints are regular (0/0)
# whipple_benchmark.al:66: DEPENDENT[1] = DOT(V_DN_N>, N1>)
# whipple_benchmark.al:67: DEPENDENT[2] = DOT(V_DN_N>, N2>)
# whipple_benchmark.al:68: DEPENDENT[3] = DOT(V_FN_N>, N1>)
# whipple_benchmark.al:69: DEPENDENT[4] = DOT(V_FN_N>, N2>)
# whipple_benchmark.al:70: DEPENDENT[5] = DOT(V_FN_N>, N3>)
# whipple_benchmark.al:71: CONSTRAIN(DEPENDENT[U1, U2, U3, U5, U8])
velocity_constraints = [
    RR*(-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))*U6*sm.cos(Q5) + RR*(sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3))*U6*sm.sin(Q5) + RR*U5*sm.cos(Q3) + U1,
    RR*(sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))*U6*sm.sin(Q5) + RR*(sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))*U6*sm.cos(Q5) + RR*U5*sm.sin(Q3) + U2,
    RF*((-sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7))*sm.cos(Q3) - sm.sin(Q3)*sm.sin(Q7)*sm.cos(Q5))*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U3/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RF*(-(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7))*U8*sm.cos(Q4)*sm.cos(Q5)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*(sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*(sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3))*U8/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RR*U3*sm.sin(Q4)*sm.cos(Q3) + (CT - RF*sm.tan(LAM))*((sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7))*U3*sm.cos(LAM) - ((sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM) + (sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM))*U3 + (-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))*(RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.cos(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U7*sm.sin(Q7)*sm.cos(LAM)) - (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.sin(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q5)*sm.cos(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - (CT - RF*sm.tan(LAM))*U7*sm.cos(LAM)*sm.cos(Q7))*sm.sin(Q3)*sm.cos(Q4) + (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U5*sm.sin(Q7)*sm.cos(Q5)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U5*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - ((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))*U5)*sm.sin(Q3)*sm.sin(Q4) + (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U5*sm.sin(Q5)*sm.sin(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RF*U5*sm.cos(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U5*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7) + (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))*U5)*sm.cos(Q3) - (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2*U4/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U4/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RR*U4*sm.cos(Q4) + (CT - RF*sm.tan(LAM))*(sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*U4*sm.cos(LAM) - (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*sm.sin(Q3) + U1,
    -RF*(-(-sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7))*sm.sin(Q3) - sm.sin(Q7)*sm.cos(Q3)*sm.cos(Q5))*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U3/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RF*((sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q5)*sm.cos(Q7))*U8*sm.cos(Q4)*sm.cos(Q5)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*(sm.sin(Q3)*sm.sin(Q5) - sm.sin(Q4)*sm.cos(Q3)*sm.cos(Q5))*(sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*U8/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RR*U3*sm.sin(Q3)*sm.sin(Q4) - (CT - RF*sm.tan(LAM))*(-(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*sm.sin(Q3) + sm.cos(Q3)*sm.cos(Q5)*sm.cos(Q7))*U3*sm.cos(LAM) + (sm.sin(Q3)*sm.cos(Q5) + sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q3))*(RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.cos(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U7*sm.sin(Q7)*sm.cos(LAM)) + ((-sm.sin(Q3)*sm.sin(Q4)*sm.sin(Q5) + sm.cos(Q3)*sm.cos(Q5))*(CT - RR*sm.tan(LAM) + W)*sm.cos(LAM) + (sm.sin(Q3)*sm.sin(Q4)*sm.cos(Q5) + sm.sin(Q5)*sm.cos(Q3))*(-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))/sm.cos(LAM))*U3 + (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.sin(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q5)*sm.cos(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - (CT - RF*sm.tan(LAM))*U7*sm.cos(LAM)*sm.cos(Q7))*sm.cos(Q3)*sm.cos(Q4) - (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U5*sm.sin(Q7)*sm.cos(Q5)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U5*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - ((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))*U5)*sm.sin(Q4)*sm.cos(Q3) + (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U5*sm.sin(Q5)*sm.sin(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RF*U5*sm.cos(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U5*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q7) + (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q5)/sm.cos(LAM))*U5)*sm.sin(Q3) + (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2*U4/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U4/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RR*U4*sm.cos(Q4) + (CT - RF*sm.tan(LAM))*(sm.sin(Q4)*sm.sin(Q7) - sm.sin(Q5)*sm.cos(Q4)*sm.cos(Q7))*U4*sm.cos(LAM) - (-(CT - RR*sm.tan(LAM) + W)*sm.sin(Q5)*sm.cos(LAM)*sm.cos(Q4) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.cos(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4)*sm.cos(Q3) + U2,
    -RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*(-sm.sin(Q4)*sm.sin(Q5)*sm.sin(Q7) + sm.cos(Q4)*sm.cos(Q7))*U4/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + RR*U4*sm.sin(Q4) - (CT - RF*sm.tan(LAM))*(sm.sin(Q4)*sm.sin(Q5)*sm.cos(Q7) + sm.sin(Q7)*sm.cos(Q4))*U4*sm.cos(LAM) + ((CT - RR*sm.tan(LAM) + W)*sm.sin(Q4)*sm.sin(Q5)*sm.cos(LAM) - (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q4)*sm.cos(Q5)/sm.cos(LAM))*U4 + (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.sin(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q5)*sm.cos(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - (CT - RF*sm.tan(LAM))*U7*sm.cos(LAM)*sm.cos(Q7))*sm.sin(Q4) - (RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U7*sm.cos(Q7)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) - RF*U7*sm.sin(Q4)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U7*sm.sin(Q7)*sm.cos(LAM))*sm.sin(Q5)*sm.cos(Q4) + (-RF*(sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))*U5*sm.sin(Q7)*sm.cos(Q5)/(1 - (sm.sin(Q4)*sm.cos(Q7) + sm.sin(Q5)*sm.sin(Q7)*sm.cos(Q4))**2)**(sm.Rational(1, 2)) + (CT - RF*sm.tan(LAM))*U5*sm.cos(LAM)*sm.cos(Q5)*sm.cos(Q7) - ((CT - RR*sm.tan(LAM) + W)*sm.cos(LAM)*sm.cos(Q5) + (-RF + RR - (CT - RF*sm.tan(LAM))*sm.sin(LAM)*sm.cos(LAM) + (CT - RR*sm.tan(LAM) + W)*sm.sin(LAM)*sm.cos(LAM))*sm.sin(Q5)/sm.cos(LAM))*U5)*sm.cos(Q4),
]
dependent = [U1, U2, U3, U5, U8]

kane = me.KanesMethod(N, q_ind=[Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8], u_ind=[U4, U6, U7], kd_eqs=kd_eqs, u_dependent=dependent, velocity_constraints=velocity_constraints, constraint_solver='CRAMER')
kane.kanes_equations(bodies, loads)

# as one system: full_mass * d(states)/dt = full_forcing
states = list(kane.q) + list(kane.u)
full_mass = kane.mass_matrix_full
full_forcing = kane.forcing_full

# the rates solved from the mass matrix, as the outputs use them
U4p = U4.diff(t)
U6p = U6.diff(t)
U7p = U7.diff(t)
intermediates = [
]
# those that need the solved rates
after_solving = [
]
unknowns = [U4p, U6p, U7p]
unknown_states = [8, 9, 10]

# values (SI units, radians) from the model's INPUT statements
constants = {CT: 0.08, G: 9.81, IBXX: 9.2, IBXZ: 2.4, IBYY: 11.0, IBZZ: 2.8, IFXX: 0.1405, IFYY: 0.28, IHXX: 0.05892, IHXZ: -0.00756, IHYY: 0.06, IHZZ: 0.00708, IRXX: 0.0603, IRYY: 0.12, LAM: 0.3141592653589793, MB: 85.0, MF: 3.0, MH: 4.0, MR: 2.0, RF: 0.35, RR: 0.3, W: 1.02, XB: 0.3, XH: 0.9, ZB: -0.9, ZH: -0.7}
initial_conditions = {Q1: 0.0, Q2: 0.0, Q3: 0.0, Q4: 0.0, Q5: 0.3141592653589793, Q6: 0.0, Q7: 0.0, Q8: 0.0, U4: 0.0, U6: -16.666666666666668, U7: 0.0}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 1.0, 'INTEGSTP': 0.1, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# scipy's method for the program's integrator: scipy has no kutta-merson (the program's)
integration_method = 'DOP853'
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('Q4', '', Q4),
    ('Q7', '', Q7),
]
# the dependent speeds start where the velocity constraints hold (once every
# constant has a value)
if None not in constants.values():
    at_start = {t: integration['TINITIAL'], **constants, **initial_conditions,
                **{s: v(integration['TINITIAL']) if callable(v) else v
                   for s, v in specified.items()}}
    coefficients, rest = sm.linear_eq_to_matrix(
        [me.msubs(c, kane.kindiffdict()) for c in velocity_constraints], dependent)
    initial_conditions.update(zip(dependent, np.linalg.solve(
        np.array(coefficients.xreplace(at_start), dtype=float),
        np.array(rest.xreplace(at_start), dtype=float).ravel())))


def expanded(expr):
    """`expr` with every intermediate replaced by what it is (large for large models)."""
    for name, value in reversed(intermediates + after_solving):
        expr = expr.xreplace({name: value})
    return expr


def numeric_functions():
    """full_mass, full_forcing and the outputs as numpy functions of (t, state, constants,
    specified values[, unknowns]), each computing the intermediates in order."""
    # every argument a Dummy: a model's constant named `sin` must not shadow numpy's
    plain = {f: sm.Dummy() for f in states + list(specified) + unknowns + list(constants)
             + [name for name, _ in intermediates + after_solving]}
    steps = [(plain[name], value.xreplace(plain)) for name, value in intermediates]
    late = [(plain[name], value.xreplace(plain)) for name, value in after_solving]
    arguments = [t, [plain[x] for x in states], [plain[c] for c in constants],
                 [plain[s] for s in specified]]

    def function(expr, more=(), after=()):
        def shared(e):
            # then sympy's common subexpressions: a KanesMethod's are not named as Z's
            common, reduced = sm.cse(e, list=False)
            return steps + list(after) + common, reduced
        return sm.lambdify(arguments + list(more), expr.xreplace(plain), "numpy", cse=shared)
    columns = sm.Matrix([e for _, _, e in outputs])
    return (function(full_mass), function(full_forcing),
            function(columns, [[plain[u] for u in unknowns]], late))


def integrate(tfinal=None):
    """The OUTPUT rows from TINITIAL to TFINAL (or `tfinal`) as Autolev's programs print
    them, as an array (a column per output)."""
    lacking = [str(c) for c, v in constants.items() if v is None]
    if lacking:
        raise ValueError(f"no value for {', '.join(lacking)}: give each in `constants`")
    mass, force, columns = numeric_functions()
    p = [constants[c] for c in constants]
    x0 = np.array([initial_conditions[x] for x in states], dtype=float)
    t0, t1 = integration["TINITIAL"], tfinal if tfinal is not None else integration["TFINAL"]

    def values_of_specified(time):
        return [v(time) if callable(v) else v for v in specified.values()]

    def rates_of(time, x):
        s = values_of_specified(time)
        return np.linalg.solve(np.asarray(mass(time, x, p, s), dtype=float),
                               np.asarray(force(time, x, p, s), dtype=float).ravel())

    def row_at(time, x):
        rate = rates_of(time, x)
        return np.asarray(columns(time, x, p, values_of_specified(time),
                                  [rate[k] for k in unknown_states]), dtype=float).ravel()

    # Autolev's loop: a step of INTEGSTP while T + INTEGSTP/100 falls short of TFINAL,
    # a row every PRINTINT steps and after the last (which may pass TFINAL)
    h, every = integration["INTEGSTP"], integration["PRINTINT"]

    def done(time):
        ahead = time + 0.01 * h
        return ahead >= t1 if t1 >= t0 else ahead <= t1
    times, time, steps = [t0], t0, 0
    while not done(time):
        time, steps = time + h, steps + 1
        if steps % every == 0 or done(time):
            times.append(time)
    if len(times) == 1:
        return np.array([row_at(t0, x0)])
    solution = solve_ivp(rates_of, (t0, times[-1]), x0, method=integration_method, t_eval=times,
                         rtol=integration["RELERR"], atol=integration["ABSERR"])
    if not solution.success:
        raise RuntimeError(solution.message)
    return np.array([row_at(time, x) for time, x in zip(solution.t, solution.y.T)])


def main(argv):
    try:
        rows = integrate()
    except ValueError as exc:
        sys.stderr.write(f"{__file__}: {exc}\n")
        return 1
    text = ",".join(label for label, _, _ in outputs) + "\n" + "".join(
        ",".join(repr(float(v)) for v in row) + "\n" for row in rows)
    if argv:
        with open(argv[0], "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
