"""Translated from double_pendulum.al by autolev.

Importing this module builds the model; running it performs the model's
CODE commands with its INPUT values."""
import autolev.runtime as al

if __name__ == "__main__":
    # `python this.py [options]` is `autolev run this.py [options]`: the same
    # messages, files and exit status
    import sys

    from autolev.cli import main
    sys.exit(main(["run", __file__, *sys.argv[1:]]))

model = al.Model('double_pendulum')
t = model.t

# double_pendulum.al -- two point masses on rigid massless links, swinging
# in the vertical plane of the Newtonian frame N (N1> points down).
#
# Written for the autolev project as a small, complete example.

# NEWTONIAN N                    % the pivot is NO, the origin of N
N = model.newtonian('N')
NO = N.origin
# FRAMES    A, B                 % link 1 and link 2
A, B = model.frames('A B')
# PARTICLES P1, P2               % the bob at the end of each link
P1, P2 = model.particles('P1 P2')

# MOTIONVARIABLES' Q{2}', U{2}'  % joint angles and their rates
Q1, Q2, U1, U2 = model.motion_variables('Q1 Q2 U1 U2', order=1)
Q1p, Q2p = al.derivatives(Q1, Q2)
# CONSTANTS L1, L2, M1, M2, G    % link lengths, masses, gravity
L1, L2, M1, M2, G = model.constants('L1 L2 M1 M2 G')

# MASS P1 = M1, P2 = M2
P1.mass = M1
P2.mass = M2

# Orientation: each link turns about the horizontal axis N3>
# SIMPROT(N, A, 3, Q1)
A.orient_axis(N, N.z, Q1)
# SIMPROT(N, B, 3, Q2)
B.orient_axis(N, N.z, Q2)

# Kinematical differential equations and angular velocities
# Q1' = U1
model.define(Q1p, U1)
# Q2' = U2
model.define(Q2p, U2)
# W_A_N> = U1*N3>
A.set_ang_vel(N, U1*N.z)
# W_B_N> = U2*N3>
B.set_ang_vel(N, U2*N.z)

# Positions and velocities
# P_NO_P1> = L1*A1>
P1.set_pos(NO, L1*A.x)
# P_P1_P2> = L2*B1>
P2.set_pos(P1, L2*B.x)
# V_NO_N>  = 0>
NO.set_vel(N, al.ZERO)
# V2PTS(N, A, NO, P1)
P1.v2pt_theory(NO, N, A)
# V2PTS(N, B, P1, P2)
P2.v2pt_theory(P1, N, B)

# Loads and equations of motion
# GRAVITY(G*N1>)
model.gravity(G*N.x)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# Energy, as a check on the integration
# KINETIC = KE()
KINETIC = model.ke()
# POTENTIAL = -M1*G*DOT(P_NO_P1>, N1>) - M2*G*DOT(P_NO_P2>, N1>)
POTENTIAL = -M1*G*al.dot(P1.pos_from(NO), N.x) - M2*G*al.dot(P2.pos_from(NO), N.x)
# ENERGY = KINETIC + POTENTIAL
ENERGY = KINETIC + POTENTIAL

# UNITSYSTEM kg, meter, sec
model.unit_system('kg', 'meter', 'sec')
# INPUT M1 = 1 kg, M2 = 1 kg, L1 = 1 m, L2 = 1 m, G = 9.81 m/sec^2
model.input(M1, 1, 'kg')
model.input(M2, 1, 'kg')
model.input(L1, 1, 'm')
model.input(L2, 1, 'm')
model.input(G, 9.81, 'm/sec^2')
# INPUT Q1 = 30 deg, Q2 = 60 deg, U1 = 0 rad/sec, U2 = 0 rad/sec
model.input(Q1, 30, 'deg')
model.input(Q2, 60, 'deg')
model.input(U1, 0, 'rad/sec')
model.input(U2, 0, 'rad/sec')
# INPUT TFINAL = 10, INTEGSTP = 0.01, ABSERR = 1.0E-08, RELERR = 1.0E-08
model.input('TFINAL', 10)
model.input('INTEGSTP', 0.01)
model.input('ABSERR', 1.0E-08)
model.input('RELERR', 1.0E-08)

# OUTPUT T sec, Q1 deg, Q2 deg, U1 rad/sec, U2 rad/sec
model.output(
    (t, 'T', 'sec'),
    (Q1, 'Q1', 'deg'),
    (Q2, 'Q2', 'deg'),
    (U1, 'U1', 'rad/sec'),
    (U2, 'U2', 'rad/sec'),
)
# OUTPUT T sec, ENERGY joules
model.output((t, 'T', 'sec'), (ENERGY, 'ENERGY', 'joules'))

# CODE DYNAMICS() double_pendulum.c
model.code('dynamics', 'double_pendulum.c', zero=ZERO)
