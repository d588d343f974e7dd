"""Translated from nlink_pendulum.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('nlink_pendulum')
t = model.t

# nlink_pendulum.al -- four uniform rods linked by pins in a vertical plane,
# the first pinned at NO.  Joint angles are relative (Q2 is the angle of link B
# from link A), the speeds are their rates.  N1> points down.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# BODIES    A, B, C, D
A, B, C, D = model.bodies('A B C D')
AO = A.masscenter
BO = B.masscenter
CO = C.masscenter
DO = D.masscenter
# POINTS    P{3}                 % the joints between the links
P1, P2, P3 = model.points('P1 P2 P3')
# MOTIONVARIABLES' Q{4}', U{4}'
Q1, Q2, Q3, Q4, U1, U2, U3, U4 = model.motion_variables('Q1 Q2 Q3 Q4 U1 U2 U3 U4', order=1)
Q1p, Q2p, Q3p, Q4p = al.derivatives(Q1, Q2, Q3, Q4)
# CONSTANTS L, M, G
L, M, G = model.constants('L M G')

# MASS A = M, B = M, C = M, D = M
A.mass = M
B.mass = M
C.mass = M
D.mass = M
# INERTIA A, 0, 0, M*L^2/12
A.set_inertia(0, 0, M*L**2/12)
# INERTIA B, 0, 0, M*L^2/12
B.set_inertia(0, 0, M*L**2/12)
# INERTIA C, 0, 0, M*L^2/12
C.set_inertia(0, 0, M*L**2/12)
# INERTIA D, 0, 0, M*L^2/12
D.set_inertia(0, 0, M*L**2/12)

# SIMPROT(N, A, 3, Q1)
A.orient_axis(N, N.z, Q1)
# SIMPROT(A, B, 3, Q2)
B.orient_axis(A, A.z, Q2)
# SIMPROT(B, C, 3, Q3)
C.orient_axis(B, B.z, Q3)
# SIMPROT(C, D, 3, Q4)
D.orient_axis(C, C.z, Q4)

# Q1' = U1
model.define(Q1p, U1)
# Q2' = U2
model.define(Q2p, U2)
# Q3' = U3
model.define(Q3p, U3)
# Q4' = U4
model.define(Q4p, U4)
# W_A_N> = U1*N3>
A.set_ang_vel(N, U1*N.z)
# W_B_A> = U2*N3>
B.set_ang_vel(A, U2*N.z)
# W_C_B> = U3*N3>
C.set_ang_vel(B, U3*N.z)
# W_D_C> = U4*N3>
D.set_ang_vel(C, U4*N.z)

# P_NO_AO> = L/2*A1>
AO.set_pos(NO, L/2*A.x)
# P_NO_P1> = L*A1>
P1.set_pos(NO, L*A.x)
# P_P1_BO> = L/2*B1>
BO.set_pos(P1, L/2*B.x)
# P_P1_P2> = L*B1>
P2.set_pos(P1, L*B.x)
# P_P2_CO> = L/2*C1>
CO.set_pos(P2, L/2*C.x)
# P_P2_P3> = L*C1>
P3.set_pos(P2, L*C.x)
# P_P3_DO> = L/2*D1>
DO.set_pos(P3, L/2*D.x)

# V2PTS(N, A, NO, AO)
AO.v2pt_theory(NO, N, A)
# V2PTS(N, A, NO, P1)
P1.v2pt_theory(NO, N, A)
# V2PTS(N, B, P1, BO)
BO.v2pt_theory(P1, N, B)
# V2PTS(N, B, P1, P2)
P2.v2pt_theory(P1, N, B)
# V2PTS(N, C, P2, CO)
CO.v2pt_theory(P2, N, C)
# V2PTS(N, C, P2, P3)
P3.v2pt_theory(P2, N, C)
# V2PTS(N, D, P3, DO)
DO.v2pt_theory(P3, N, D)

# GRAVITY(G*N1>)
model.gravity(G*N.x)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT L = 0.5 m, M = 1 kg, G = 9.81 m/sec^2
model.input(L, 0.5, 'm')
model.input(M, 1, 'kg')
model.input(G, 9.81, 'm/sec^2')
# INPUT Q1 = 20 deg, Q2 = 10 deg, Q3 = -10 deg, Q4 = 5 deg
model.input(Q1, 20, 'deg')
model.input(Q2, 10, 'deg')
model.input(Q3, -10, 'deg')
model.input(Q4, 5, 'deg')
# INPUT U1 = 0, U2 = 0, U3 = 0, U4 = 0
model.input(U1, 0)
model.input(U2, 0)
model.input(U3, 0)
model.input(U4, 0)
# INPUT TFINAL = 3, INTEGSTP = 0.01
model.input('TFINAL', 3)
model.input('INTEGSTP', 0.01)
# OUTPUT T sec, Q1 deg, Q2 deg, Q3 deg, Q4 deg
model.output(
    (t, 'T', 'sec'),
    (Q1, 'Q1', 'deg'),
    (Q2, 'Q2', 'deg'),
    (Q3, 'Q3', 'deg'),
    (Q4, 'Q4', 'deg'),
)
# CODE DYNAMICS() nlink_pendulum.c
model.code('dynamics', 'nlink_pendulum.c', zero=ZERO)
