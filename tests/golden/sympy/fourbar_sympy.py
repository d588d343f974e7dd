"""fourbar: the model in sympy.physics.mechanics, written by autolev from
fourbar.al (CODE DYNAMICS fourbar.c).

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
U1 = me.dynamicsymbols('U1')
U2 = me.dynamicsymbols('U2')
U3 = me.dynamicsymbols('U3')

# auxiliary speeds: zero in motion, they bring noncontributing forces into evidence
# fourbar.al:50: AUXILIARY[1] = UA1
# fourbar.al:51: AUXILIARY[2] = UA2
# fourbar.al:52: CONSTRAIN(AUXILIARY[UA1, UA2])
UA1 = me.dynamicsymbols('UA1')
UA2 = me.dynamicsymbols('UA2')
auxiliary = [UA1, UA2]

# KANE's unknowns: noncontributing forces, which kane.auxiliary_eqs (= 0) give
F1 = me.dynamicsymbols('F1')
F2 = me.dynamicsymbols('F2')

# constants
L1 = sm.Symbol('L1')
L2 = sm.Symbol('L2')
L3 = sm.Symbol('L3')
L4 = sm.Symbol('L4')
RHO = sm.Symbol('RHO')
G = sm.Symbol('G')

# reference frames, oriented as the model orients them, with its angular velocities
N = me.ReferenceFrame('N')
# fourbar.al:19: SIMPROT(N, B2, 3, Q1)
# fourbar.al:25: W_B2_N> = U1*N3>
B2 = me.ReferenceFrame('B2')
B2.orient_axis(N, N.z, Q1)
B2.set_ang_vel(N, U1*N.z)
# fourbar.al:20: SIMPROT(B2, B3, 3, Q2)
# fourbar.al:26: W_B3_B2> = U2*N3>
B3 = me.ReferenceFrame('B3')
B3.orient_axis(B2, B2.z, Q2)
B3.set_ang_vel(B2, U2*N.z)
# fourbar.al:21: SIMPROT(B3, B4, 3, Q3)
# fourbar.al:27: W_B4_B3> = U3*N3>
B4 = me.ReferenceFrame('B4')
B4.orient_axis(B3, B3.z, Q3)
B4.set_ang_vel(B3, U3*N.z)

# points: positions from the Newtonian origin, velocities in N of those with a mass or a load
B2O = me.Point('B2O')
B3O = me.Point('B3O')
B4O = me.Point('B4O')
PA = me.Point('PA')
P2 = me.Point('P2')
NO = me.Point('NO')
P3 = me.Point('P3')
P4 = me.Point('P4')
P5 = me.Point('P5')
# fourbar.al:29: P_NO_P2> = L1*N1>
P2.set_pos(NO, L1*N.x)
# fourbar.al:30: P_P2_B2O> = L2/2*B21>
B2O.set_pos(P2, L2/2*B2.x)
# fourbar.al:31: P_P2_P3> = L2*B21>
P3.set_pos(P2, L2*B2.x)
# fourbar.al:32: P_P3_B3O> = L3/2*B31>
B3O.set_pos(P3, L3/2*B3.x)
# fourbar.al:33: P_P3_P4> = L3*B31>
P4.set_pos(P3, L3*B3.x)
# fourbar.al:34: P_P4_B4O> = L4/2*B41>
B4O.set_pos(P4, L4/2*B4.x)
# fourbar.al:35: P_P4_P5> = L4*B41>
P5.set_pos(P4, L4*B4.x)
# fourbar.al:38: V2PTS(N, B2, P2, B2O)
B2O.set_vel(N, (-L2*U1*sm.sin(Q1)/2)*N.x + L2*U1*sm.cos(Q1)/2*N.y)
# fourbar.al:40: V2PTS(N, B3, P3, B3O)
B3O.set_vel(N, (-L2*U1*sm.sin(Q1) - L3*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2)/2)*N.x + (L2*U1*sm.cos(Q1) + L3*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2)/2)*N.y)
# fourbar.al:42: V2PTS(N, B4, P4, B4O)
B4O.set_vel(N, (-L2*U1*sm.sin(Q1) - L3*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2) - L4*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.sin(Q1) + (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.cos(Q1))*(U1 + U2 + U3)/2)*N.x + (L2*U1*sm.cos(Q1) + L3*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2) + L4*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.cos(Q1) - (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.sin(Q1))*(U1 + U2 + U3)/2)*N.y)
# fourbar.al:49: V_PA_N> = UA1*N1> + UA2*N2>
PA.set_vel(N, UA1*N.x + UA2*N.y)

# particles and rigid bodies: masses and central inertias
# fourbar.al:14: MASS B2 = RHO*L2, B3 = RHO*L3, B4 = RHO*L4
# fourbar.al:15: INERTIA B2, 0, 0, RHO*L2^3/12
B2_body = me.RigidBody('B2', B2O, B2, L2*RHO, (me.inertia(B2, 0, 0, L2**3*RHO/12), B2O))
# fourbar.al:14: MASS B2 = RHO*L2, B3 = RHO*L3, B4 = RHO*L4
# fourbar.al:16: INERTIA B3, 0, 0, RHO*L3^3/12
B3_body = me.RigidBody('B3', B3O, B3, L3*RHO, (me.inertia(B3, 0, 0, L3**3*RHO/12), B3O))
# fourbar.al:14: MASS B2 = RHO*L2, B3 = RHO*L3, B4 = RHO*L4
# fourbar.al:17: INERTIA B4, 0, 0, RHO*L4^3/12
B4_body = me.RigidBody('B4', B4O, B4, L4*RHO, (me.inertia(B4, 0, 0, L4**3*RHO/12), B4O))
bodies = [B2_body, B3_body, B4_body]

# loads: forces on points, torques on frames
# fourbar.al:54: GRAVITY(-G*N2>)
loads = [
    (B2O, (-G*L2*RHO)*N.y),
    (B3O, (-G*L3*RHO)*N.y),
    (B4O, (-G*L4*RHO)*N.y),
    # fourbar.al:55: FORCE_PA> = F1*N1> + F2*N2>
    (PA, F1*N.x + F2*N.y),
]

# kinematical differential equations (each = 0)
kd_eqs = [
    # fourbar.al:22: Q1' = U1
    Q1.diff(t) - U1,
    # fourbar.al:23: Q2' = U2
    Q2.diff(t) - U2,
    # fourbar.al:24: Q3' = U3
    Q3.diff(t) - U3,
]

# velocity constraints (each = 0), which give the dependent speeds (CONSTRAIN(DEPENDENT[...]));
# KanesMethod solves them by Cramer's rule: its default LU divides by pivots that
# vanish at some states where the constraints are regular (0/0)
# fourbar.al:46: DEPENDENT[1] = DOT(V_P5_N>, N1>) + UA1
# fourbar.al:47: DEPENDENT[2] = DOT(V_P5_N>, N2>) + UA2
# fourbar.al:48: CONSTRAIN(DEPENDENT[U2, U3])
velocity_constraints = [
    -L2*U1*sm.sin(Q1) - L3*(sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1))*(U1 + U2) - L4*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.sin(Q1) + (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.cos(Q1))*(U1 + U2 + U3) + UA1,
    L2*U1*sm.cos(Q1) + L3*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))*(U1 + U2) + L4*((-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))*sm.cos(Q1) - (sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2))*sm.sin(Q1))*(U1 + U2 + U3) + UA2,
]
dependent = [U2, U3]

kane = me.KanesMethod(N, q_ind=[Q1, Q2, Q3], u_ind=[U1], kd_eqs=kd_eqs, u_dependent=dependent, velocity_constraints=velocity_constraints, constraint_solver='CRAMER', u_auxiliary=auxiliary)
kane.kanes_equations(bodies, loads)

# as one system: full_mass * d(states)/dt = full_forcing
states = list(kane.q) + list(kane.u)
# the auxiliary speeds, which the velocity constraints read, are zero in motion
full_mass, full_forcing = (
    m.xreplace({u.diff(t): 0 for u in auxiliary}).xreplace(dict.fromkeys(auxiliary, 0))
    for m in (kane.mass_matrix_full, kane.forcing_full))

# the rates solved from the mass matrix, as the outputs use them
U1p = U1.diff(t)
# intermediates the outputs use (Autolev's Z's, the model's definitions), as
# functions of time, and what each is, in the order they are computed
z4 = me.dynamicsymbols('z4')
z6 = me.dynamicsymbols('z6')
z7 = me.dynamicsymbols('z7')
z1 = me.dynamicsymbols('z1')
z3 = me.dynamicsymbols('z3')
z9 = me.dynamicsymbols('z9')
z14 = me.dynamicsymbols('z14')
z31 = me.dynamicsymbols('z31')
z32 = me.dynamicsymbols('z32')
z36 = me.dynamicsymbols('z36')
z39 = me.dynamicsymbols('z39')
z46 = me.dynamicsymbols('z46')
z42 = me.dynamicsymbols('z42')
z47 = me.dynamicsymbols('z47')
Q1p = me.dynamicsymbols('Q1p')
UA1_2 = me.dynamicsymbols('UA1_2')
UA2_2 = me.dynamicsymbols('UA2_2')
z15 = me.dynamicsymbols('z15')
U2_2 = me.dynamicsymbols('U2_2')
Q2p = me.dynamicsymbols('Q2p')
z17 = me.dynamicsymbols('z17')
z18 = me.dynamicsymbols('z18')
z16 = me.dynamicsymbols('z16')
U3_2 = me.dynamicsymbols('U3_2')
Q3p = me.dynamicsymbols('Q3p')
z19 = me.dynamicsymbols('z19')
z20 = me.dynamicsymbols('z20')
z21 = me.dynamicsymbols('z21')
z22 = me.dynamicsymbols('z22')
z23 = me.dynamicsymbols('z23')
UA1p = me.dynamicsymbols('UA1p')
UA2p = me.dynamicsymbols('UA2p')
z66 = me.dynamicsymbols('z66')
z71 = me.dynamicsymbols('z71')
z33 = me.dynamicsymbols('z33')
z34 = me.dynamicsymbols('z34')
z37 = me.dynamicsymbols('z37')
z40 = me.dynamicsymbols('z40')
z48 = me.dynamicsymbols('z48')
z43 = me.dynamicsymbols('z43')
z49 = me.dynamicsymbols('z49')
z67 = me.dynamicsymbols('z67')
z72 = me.dynamicsymbols('z72')
z24 = me.dynamicsymbols('z24')
z25 = me.dynamicsymbols('z25')
U2p = me.dynamicsymbols('U2p')
z55 = me.dynamicsymbols('z55')
z56 = me.dynamicsymbols('z56')
z57 = me.dynamicsymbols('z57')
z26 = me.dynamicsymbols('z26')
z27 = me.dynamicsymbols('z27')
U3p = me.dynamicsymbols('U3p')
z59 = me.dynamicsymbols('z59')
z61 = me.dynamicsymbols('z61')
z60 = me.dynamicsymbols('z60')
z62 = me.dynamicsymbols('z62')
z63 = me.dynamicsymbols('z63')
z69 = me.dynamicsymbols('z69')
z70 = me.dynamicsymbols('z70')
intermediates = [
    (z4, -sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3)),
    (z6, sm.sin(Q2)*sm.cos(Q3) + sm.sin(Q3)*sm.cos(Q2)),
    (z7, z4*sm.cos(Q1) - z6*sm.sin(Q1)),
    (z1, -sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2)),
    (z3, sm.sin(Q1)*sm.cos(Q2) + sm.sin(Q2)*sm.cos(Q1)),
    (z9, z4*sm.sin(Q1) + z6*sm.cos(Q1)),
    (z14, L4*z7*(-L3*z3 - L4*z9) + L4*z9*(L3*z1 + L4*z7)),
    (z31, L3*L4*z3*z7/(2*z14)),
    (z32, -L3*L4*z1*z7/(2*z14)),
    (z36, (L3*z1 + L4*z7)/z14),
    (z39, L4**2*z7*z9/(2*z14) - L4*z36*z9/2),
    (z46, L3*L4*z3*z7/z14 + z39),
    (z42, -L4**2*z7**2/(2*z14) + L4*z36*z7/2),
    (z47, -L3*L4*z1*z7/z14 + z42),
    (Q1p, U1),
    (UA1_2, sm.sympify(0)),
    (UA2_2, sm.sympify(0)),
    (z15, L4*z7*(L2*U1*sm.sin(Q1) + L3*U1*z3 + L4*U1*z9 - UA1_2) + L4*z9*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2_2)),
    (U2_2, z15/z14),
    (Q2p, U2_2),
    (z17, Q1p*(-sm.sin(Q1)*sm.cos(Q2) - sm.sin(Q2)*sm.cos(Q1)) + Q2p*(-sm.sin(Q1)*sm.cos(Q2) - sm.sin(Q2)*sm.cos(Q1))),
    (z18, Q1p*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2)) + Q2p*(-sm.sin(Q1)*sm.sin(Q2) + sm.cos(Q1)*sm.cos(Q2))),
    (z16, (L3*z1 + L4*z7)*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1_2) + (-L3*z3 - L4*z9)*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2_2)),
    (U3_2, z16/z14),
    (Q3p, U3_2),
    (z19, Q2p*(-sm.sin(Q2)*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q2)) + Q3p*(-sm.sin(Q2)*sm.cos(Q3) - sm.sin(Q3)*sm.cos(Q2))),
    (z20, Q2p*(-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3)) + Q3p*(-sm.sin(Q2)*sm.sin(Q3) + sm.cos(Q2)*sm.cos(Q3))),
    (z21, Q1p*(-z4*sm.sin(Q1) - z6*sm.cos(Q1)) + z19*sm.cos(Q1) - z20*sm.sin(Q1)),
    (z22, Q1p*(z4*sm.cos(Q1) - z6*sm.sin(Q1)) + z19*sm.sin(Q1) + z20*sm.cos(Q1)),
    (z23, L3*L4*z17*z9 - L3*L4*z18*z7 + z21*(L4**2*z9 + L4*(-L3*z3 - L4*z9)) + z22*(-L4**2*z7 + L4*(L3*z1 + L4*z7))),
    (UA1p, sm.sympify(0)),
    (UA2p, sm.sympify(0)),
    (z66, -L4*z7/z14 + z36),
    (z71, -G*L3*RHO*z32 - G*L4*RHO*z47),
    (z33, L3*L4*z3*z9/(2*z14)),
    (z34, -L3*L4*z1*z9/(2*z14)),
    (z37, (L3*z3 + L4*z9)/z14),
    (z40, L4**2*z9**2/(2*z14) - L4*z37*z9/2),
    (z48, L3*L4*z3*z9/z14 + z40),
    (z43, -L4**2*z7*z9/(2*z14) + L4*z37*z7/2),
    (z49, -L3*L4*z1*z9/z14 + z43),
    (z67, -L4*z9/z14 + z37),
    (z72, -G*L3*RHO*z34 - G*L4*RHO*z49),
]
# those that need the solved rates
after_solving = [
    (z24, -L3*L4*U1*z17*z9 + L3*L4*U1*z18*z7 - L4*UA1p*z7 - L4*UA2p*z9 + Q1p*(L2*L4*U1*z7*sm.cos(Q1) + L2*L4*U1*z9*sm.sin(Q1)) + U1p*(L4*z7*(L2*sm.sin(Q1) + L3*z3 + L4*z9) + L4*z9*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)) + z21*(-L4**2*U1*z9 + L4*(L2*U1*sm.sin(Q1) + L3*U1*z3 + L4*U1*z9 - UA1_2)) + z22*(L4**2*U1*z7 + L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2_2))),
    (z25, z24/z14 - z15*z23/z14**2),
    (U2p, z25),
    (z55, -L2*Q1p*U1*sm.cos(Q1) - L3*U2p*z3/2 - L3*z18*(U1 + U2_2)/2 + U1p*(-L2*sm.sin(Q1) - L3*z3/2)),
    (z56, -L2*Q1p*U1*sm.sin(Q1) + L3*U2p*z1/2 + L3*z17*(U1 + U2_2)/2 + U1p*(L2*sm.cos(Q1) + L3*z1/2)),
    (z57, L3**3*RHO*(U1p + U2p)/12),
    (z26, Q1p*(-L2*U1*(L3*z1 + L4*z7)*sm.cos(Q1) + L2*U1*(-L3*z3 - L4*z9)*sm.sin(Q1)) + U1p*((L3*z1 + L4*z7)*(-L2*sm.sin(Q1) - L3*z3 - L4*z9) + (-L3*z3 - L4*z9)*(-L2*sm.cos(Q1) - L3*z1 - L4*z7)) + UA1p*(L3*z1 + L4*z7) + UA2p*(L3*z3 + L4*z9) + z17*(-L3*U1*(-L3*z3 - L4*z9) + L3*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1_2)) + z18*(-L3*U1*(L3*z1 + L4*z7) - L3*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2_2)) + z21*(-L4*U1*(-L3*z3 - L4*z9) + L4*(-L2*U1*sm.sin(Q1) - L3*U1*z3 - L4*U1*z9 + UA1_2)) + z22*(-L4*U1*(L3*z1 + L4*z7) - L4*(-L2*U1*sm.cos(Q1) - L3*U1*z1 - L4*U1*z7 - UA2_2))),
    (z27, z26/z14 - z16*z23/z14**2),
    (U3p, z27),
    (z59, -L4*U1p*z9/2 - L4*U2p*z9/2 - L4*U3p*z9/2 - L4*z22*(U1 + U2_2 + U3_2)/2),
    (z61, -L2*Q1p*U1*sm.cos(Q1) - L3*U2p*z3 - L3*z18*(U1 + U2_2) + U1p*(-L2*sm.sin(Q1) - L3*z3) + z59),
    (z60, L4*U1p*z7/2 + L4*U2p*z7/2 + L4*U3p*z7/2 + L4*z21*(U1 + U2_2 + U3_2)/2),
    (z62, -L2*Q1p*U1*sm.sin(Q1) + L3*U2p*z1 + L3*z17*(U1 + U2_2) + U1p*(L2*sm.cos(Q1) + L3*z1) + z60),
    (z63, L4**3*RHO*(U1p + U2p + U3p)/12),
    (z69, -L3*RHO*z31*z55 - L3*RHO*z32*z56 - L4*RHO*z46*z61 - L4*RHO*z47*z62 + L4*z57*z7/z14 - z63*z66),
    (F1, -z69 - z71),
    (z70, -L3*RHO*z33*z55 - L3*RHO*z34*z56 - L4*RHO*z48*z61 - L4*RHO*z49*z62 + L4*z57*z9/z14 - z63*z67),
    (F2, -z70 - z72),
]
unknowns = [U1p]
unknown_states = [3]

# values (SI units, radians) from the model's INPUT statements
constants = {G: 9.81, L2: 1.0, L3: 2.0, L4: 1.0, RHO: 5.0}
initial_conditions = {Q1: 1.5707963267948966, Q2: 1.5707963267948966, Q3: 1.5707963267948966, U1: 0.5}
# each a number or a function of time; 0 unless given
specified = {}
integration = {'TINITIAL': 0.0, 'TFINAL': 2.0, 'INTEGSTP': 0.01, 'ABSERR': 1e-08, 'RELERR': 1e-07, 'PRINTINT': 1}
# scipy's method for the program's integrator: scipy has no kutta-merson (the program's)
integration_method = 'DOP853'
# OUTPUT columns: (label, unit, expression in the unit)
outputs = [
    ('T', 'sec', t),
    ('Q1', 'deg', Q1 * 180 / sm.pi),
    ('Q2', 'deg', Q2 * 180 / sm.pi),
    ('Q3', 'deg', Q3 * 180 / sm.pi),
    ('F1', 'N', F1),
    ('F2', 'N', F2),
]
# the dependent speeds start where the velocity constraints hold (once every
# constant has a value)
if None not in constants.values():
    at_start = {t: integration['TINITIAL'], **constants, **initial_conditions,
                **{s: v(integration['TINITIAL']) if callable(v) else v
                   for s, v in specified.items()}, **dict.fromkeys(auxiliary, 0)}
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
