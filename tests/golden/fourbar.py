"""Translated from fourbar.al by autolev.

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

model = al.Model('fourbar')
t = model.t

# fourbar.al -- four uniform links, link 1 being the ground N.  Joint angles Q1,
# Q2, Q3 (each link relative to the one before, about N3>); the loop closes where
# the free end of link 4 meets the start of link 1, so Q2 and Q3 follow Q1.
# Two auxiliary speeds give the closing point extra velocity, revealing the
# force (F1, F2) the closing joint carries.  N2> is up.

# NEWTONIAN N                    % link 1, from NO to P2
N = model.newtonian('N')
NO = N.origin
# BODIES    B2, B3, B4           % links 2, 3, 4
B2, B3, B4 = model.bodies('B2 B3 B4')
B2O = B2.masscenter
B3O = B3.masscenter
B4O = B4.masscenter
# POINTS    P2, P3, P4, P5, PA   % the joints, the free end, the auxiliary point
P2, P3, P4, P5, PA = model.points('P2 P3 P4 P5 PA')
# MOTIONVARIABLES' Q{3}', U{3}', UA{2}'
Q1, Q2, Q3, U1, U2, U3, UA1, UA2 = model.motion_variables('Q1 Q2 Q3 U1 U2 U3 UA1 UA2', order=1)
Q1p, Q2p, Q3p = al.derivatives(Q1, Q2, Q3)
# VARIABLES F1, F2
F1, F2 = model.variables('F1 F2')
# CONSTANTS L1, L2, L3, L4, RHO, G
L1, L2, L3, L4, RHO, G = model.constants('L1 L2 L3 L4 RHO G')

# MASS B2 = RHO*L2, B3 = RHO*L3, B4 = RHO*L4
B2.mass = RHO*L2
B3.mass = RHO*L3
B4.mass = RHO*L4
# INERTIA B2, 0, 0, RHO*L2^3/12
B2.set_inertia(0, 0, RHO*L2**3/12)
# INERTIA B3, 0, 0, RHO*L3^3/12
B3.set_inertia(0, 0, RHO*L3**3/12)
# INERTIA B4, 0, 0, RHO*L4^3/12
B4.set_inertia(0, 0, RHO*L4**3/12)

# SIMPROT(N, B2, 3, Q1)
B2.orient_axis(N, N.z, Q1)
# SIMPROT(B2, B3, 3, Q2)
B3.orient_axis(B2, B2.z, Q2)
# SIMPROT(B3, B4, 3, Q3)
B4.orient_axis(B3, B3.z, Q3)
# Q1' = U1
model.define(Q1p, U1)
# Q2' = U2
model.define(Q2p, U2)
# Q3' = U3
model.define(Q3p, U3)
# W_B2_N> = U1*N3>
B2.set_ang_vel(N, U1*N.z)
# W_B3_B2> = U2*N3>
B3.set_ang_vel(B2, U2*N.z)
# W_B4_B3> = U3*N3>
B4.set_ang_vel(B3, U3*N.z)

# P_NO_P2> = L1*N1>
P2.set_pos(NO, L1*N.x)
# P_P2_B2O> = L2/2*B21>
B2O.set_pos(P2, L2/2*B2.x)
# P_P2_P3> = L2*B21>
P3.set_pos(P2, L2*B2.x)
# P_P3_B3O> = L3/2*B31>
B3O.set_pos(P3, L3/2*B3.x)
# P_P3_P4> = L3*B31>
P4.set_pos(P3, L3*B3.x)
# P_P4_B4O> = L4/2*B41>
B4O.set_pos(P4, L4/2*B4.x)
# P_P4_P5> = L4*B41>
P5.set_pos(P4, L4*B4.x)

# V_P2_N> = 0>
P2.set_vel(N, al.ZERO)
# V2PTS(N, B2, P2, B2O)
B2O.v2pt_theory(P2, N, B2)
# V2PTS(N, B2, P2, P3)
P3.v2pt_theory(P2, N, B2)
# V2PTS(N, B3, P3, B3O)
B3O.v2pt_theory(P3, N, B3)
# V2PTS(N, B3, P3, P4)
P4.v2pt_theory(P3, N, B3)
# V2PTS(N, B4, P4, B4O)
B4O.v2pt_theory(P4, N, B4)
# V2PTS(N, B4, P4, P5)
P5.v2pt_theory(P4, N, B4)

# the free end of link 4 stays at NO; the auxiliary speeds let it move
# DEPENDENT[1] = DOT(V_P5_N>, N1>) + UA1
# DEPENDENT[2] = DOT(V_P5_N>, N2>) + UA2
DEPENDENT = sm.Matrix([al.dot(P5.vel(N), N.x) + UA1, al.dot(P5.vel(N), N.y) + UA2])
# CONSTRAIN(DEPENDENT[U2, U3])
model.constrain(DEPENDENT, [U2, U3])
# V_PA_N> = UA1*N1> + UA2*N2>
PA.set_vel(N, UA1*N.x + UA2*N.y)
# AUXILIARY[1] = UA1
# AUXILIARY[2] = UA2
AUXILIARY = sm.Matrix([UA1, UA2])
# CONSTRAIN(AUXILIARY[UA1, UA2])
model.constrain_auxiliary(AUXILIARY, [UA1, UA2])

# GRAVITY(-G*N2>)
model.gravity(-G*N.y)
# FORCE_PA> = F1*N1> + F2*N2>
model.set_force(PA, F1*N.x + F2*N.y)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE(F1, F2)
model.kane(F1, F2)

# INPUT L1 = 2 m, L2 = 1 m, L3 = 2 m, L4 = 1 m, RHO = 5 kg/m, G = 9.81 m/sec^2
model.input(L1, 2, 'm')
model.input(L2, 1, 'm')
model.input(L3, 2, 'm')
model.input(L4, 1, 'm')
model.input(RHO, 5, 'kg/m')
model.input(G, 9.81, 'm/sec^2')
# INPUT Q1 = 90 deg, Q2 = 90 deg, Q3 = 90 deg, U1 = 0.5 rad/sec
model.input(Q1, 90, 'deg')
model.input(Q2, 90, 'deg')
model.input(Q3, 90, 'deg')
model.input(U1, 0.5, 'rad/sec')
# INPUT TFINAL = 2, INTEGSTP = 0.01
model.input('TFINAL', 2)
model.input('INTEGSTP', 0.01)
# OUTPUT T sec, Q1 deg, Q2 deg, Q3 deg, F1 N, F2 N
model.output(
    (t, 'T', 'sec'),
    (Q1, 'Q1', 'deg'),
    (Q2, 'Q2', 'deg'),
    (Q3, 'Q3', 'deg'),
    (F1, 'F1', 'N'),
    (F2, 'F2', 'N'),
)
# CODE DYNAMICS() fourbar.c
model.code('dynamics', 'fourbar.c', zero=ZERO)
