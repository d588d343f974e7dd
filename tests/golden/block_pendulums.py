"""Translated from block_pendulums.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('block_pendulums')
t = model.t

# block_pendulums.al -- a block sliding along the floor away from a wall, carrying
# a compound pendulum B that carries a simple pendulum (bob C on a massless rod).
# The block is held by a spring and damper to the wall and pushed by a force
# F(t); a torque TQ(t) acts on B from the wall; a torsional spring acts between
# the rod of C and B.  N2> is up.

# NEWTONIAN N                    % the wall and floor
N = model.newtonian('N')
NO = N.origin
# PARTICLES A, C                 % the block; the simple pendulum's bob
A, C = model.particles('A C')
# BODIES    B                    % the compound pendulum
B = model.bodies('B')
BO = B.masscenter
# FRAMES    CF                   % the simple pendulum's rod
CF = model.frames('CF')
# POINTS    PBC                  % the pin between B and the rod
PBC = model.points('PBC')
# MOTIONVARIABLES' Q{3}', U{3}'
Q1, Q2, Q3, U1, U2, U3 = model.motion_variables('Q1 Q2 Q3 U1 U2 U3', order=1)
Q1p, Q2p, Q3p = al.derivatives(Q1, Q2, Q3)
# CONSTANTS MA, MB, MC, IBZZ, L, G, K, CDAMP, KT
MA, MB, MC, IBZZ, L, G, K, CDAMP, KT = model.constants('MA MB MC IBZZ L G K CDAMP KT')
# SPECIFIED F, TQ
F, TQ = model.specifieds('F TQ')

# MASS A = MA, B = MB, C = MC
A.mass = MA
B.mass = MB
C.mass = MC
# INERTIA B, 0, 0, IBZZ
B.set_inertia(0, 0, IBZZ)

# SIMPROT(N, B, 3, Q2)           % Q2: B from the vertical
B.orient_axis(N, N.z, Q2)
# SIMPROT(B, CF, 3, Q3)          % Q3: the rod relative to B
CF.orient_axis(B, B.z, Q3)
# Q1' = U1
model.define(Q1p, U1)
# Q2' = U2
model.define(Q2p, U2)
# Q3' = U3
model.define(Q3p, U3)
# W_B_N> = U2*N3>
B.set_ang_vel(N, U2*N.z)
# W_CF_B> = U3*N3>
CF.set_ang_vel(B, U3*N.z)

# P_NO_A> = Q1*N1>
A.set_pos(NO, Q1*N.x)
# V_A_N> = U1*N1>
A.set_vel(N, U1*N.x)
# P_A_BO> = -2*L/3*B2>
BO.set_pos(A, -2*L/3*B.y)
# P_BO_PBC> = -L/3*B2>
PBC.set_pos(BO, -L/3*B.y)
# P_PBC_C> = -L*CF2>
C.set_pos(PBC, -L*CF.y)
# V2PTS(N, B, A, BO)
BO.v2pt_theory(A, N, B)
# V2PTS(N, B, A, PBC)
PBC.v2pt_theory(A, N, B)
# V2PTS(N, CF, PBC, C)
C.v2pt_theory(PBC, N, CF)

# GRAVITY(-G*N2>)
model.gravity(-G*N.y)
# FORCE(NO/A, (-K*Q1 - CDAMP*U1)*N1>)
model.force_pair(NO, A, (-K*Q1 - CDAMP*U1)*N.x)
# FORCE(A, F*N1>)
model.force(A, F*N.x)
# TORQUE(N/B, TQ*N3>)
model.torque_pair(N, B, TQ*N.z)
# TORQUE(B/CF, -KT*Q3*N3>)
model.torque_pair(B, CF, -KT*Q3*N.z)

# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT MA = 2, MB = 1, MC = 0.5, IBZZ = 0.1, L = 1, G = 9.81, K = 20, CDAMP = 0.5
model.input(MA, 2)
model.input(MB, 1)
model.input(MC, 0.5)
model.input(IBZZ, 0.1)
model.input(L, 1)
model.input(G, 9.81)
model.input(K, 20)
model.input(CDAMP, 0.5)
# INPUT KT = 2
model.input(KT, 2)
# INPUT Q1 = 0.1, Q2 = 20 deg, Q3 = -10 deg, U1 = 0, U2 = 0, U3 = 0
model.input(Q1, 0.1)
model.input(Q2, 20, 'deg')
model.input(Q3, -10, 'deg')
model.input(U1, 0)
model.input(U2, 0)
model.input(U3, 0)
# INPUT TFINAL = 5, INTEGSTP = 0.01
model.input('TFINAL', 5)
model.input('INTEGSTP', 0.01)
# OUTPUT T, Q1, Q2 deg, Q3 deg
model.output((t, 'T'), (Q1, 'Q1'), (Q2, 'Q2', 'deg'), (Q3, 'Q3', 'deg'))
# CODE DYNAMICS() block_pendulums.c
model.code('dynamics', 'block_pendulums.c', zero=ZERO)
