"""Translated from rolling_disc.al by autolev.

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

model = al.Model('rolling_disc')
t = model.t

# rolling_disc.al -- a thin disc rolling without slip on the horizontal plane of
# N (N3> up).  Q1 yaw, Q2 lean, Q3 spin; Q4, Q5 locate the contact point.  The
# no-slip conditions make U4 and U5 dependent speeds.

# NEWTONIAN N
N = model.newtonian('N')
NO = N.origin
# FRAMES    A, B                 % yaw frame, lean frame
A, B = model.frames('A B')
# BODIES    C                    % the disc; C2> is its axis
C = model.bodies('C')
CO = C.masscenter
# POINTS    CN                   % the disc's point in contact with the ground
CN = model.points('CN')
# MOTIONVARIABLES' Q{5}', U{5}'
Q1, Q2, Q3, Q4, Q5, U1, U2, U3, U4, U5 = model.motion_variables('Q1 Q2 Q3 Q4 Q5 U1 U2 U3 U4 U5', order=1)
Q1p, Q2p, Q3p, Q4p, Q5p = al.derivatives(Q1, Q2, Q3, Q4, Q5)
# CONSTANTS R, M, G
R, M, G = model.constants('R M G')

# MASS C = M
C.mass = M
# INERTIA C, M*R^2/4, M*R^2/2, M*R^2/4
C.set_inertia(M*R**2/4, M*R**2/2, M*R**2/4)

# SIMPROT(N, A, 3, Q1)
A.orient_axis(N, N.z, Q1)
# SIMPROT(A, B, 1, Q2)
B.orient_axis(A, A.x, Q2)
# SIMPROT(B, C, 2, Q3)
C.orient_axis(B, B.y, Q3)
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

# P_NO_CO> = Q4*N1> + Q5*N2> + R*B3>
CO.set_pos(NO, Q4*N.x + Q5*N.y + R*B.z)
# V_CO_N> = DT(P_NO_CO>, N)
CO.set_vel(N, model.dt(CO.pos_from(NO), N))
# P_CO_CN> = -R*B3>
CN.set_pos(CO, -R*B.z)
# V2PTS(N, C, CO, CN)
CN.v2pt_theory(CO, N, C)

# rolling without slip: the contact point of the disc is at rest
# DEPENDENT[1] = DOT(V_CN_N>, N1>)
# DEPENDENT[2] = DOT(V_CN_N>, N2>)
DEPENDENT = sm.Matrix([al.dot(CN.vel(N), N.x), al.dot(CN.vel(N), N.y)])
# CONSTRAIN(DEPENDENT[U4, U5])
model.constrain(DEPENDENT, [U4, U5])

# GRAVITY(-G*N3>)
model.gravity(-G*N.z)
# ZERO = FR() + FRSTAR()
ZERO = model.fr() + model.frstar()
# KANE()
model.kane()

# INPUT R = 0.3 m, M = 2 kg, G = 9.81 m/sec^2
model.input(R, 0.3, 'm')
model.input(M, 2, 'kg')
model.input(G, 9.81, 'm/sec^2')
# INPUT Q1 = 0, Q2 = 5 deg, Q3 = 0, Q4 = 0, Q5 = 0
model.input(Q1, 0)
model.input(Q2, 5, 'deg')
model.input(Q3, 0)
model.input(Q4, 0)
model.input(Q5, 0)
# INPUT U1 = 0, U2 = 0, U3 = 8 rad/sec
model.input(U1, 0)
model.input(U2, 0)
model.input(U3, 8, 'rad/sec')
# INPUT TFINAL = 3, INTEGSTP = 0.01
model.input('TFINAL', 3)
model.input('INTEGSTP', 0.01)
# OUTPUT T sec, Q1 deg, Q2 deg, Q4 m, Q5 m
model.output(
    (t, 'T', 'sec'),
    (Q1, 'Q1', 'deg'),
    (Q2, 'Q2', 'deg'),
    (Q4, 'Q4', 'm'),
    (Q5, 'Q5', 'm'),
)
# CODE DYNAMICS() rolling_disc.c
model.code('dynamics', 'rolling_disc.c', zero=ZERO)
